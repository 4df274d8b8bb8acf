#pragma once
// A smooth 2D vector field over the map sampled at scattered points: values are spread onto a
// regular grid with bilinear (tent) weights, normalized, grown outwards into the nodes that no
// sample reached, and read back bilinearly. Used to carry a coarse relaxation onto a finer lattice
// (solver/coarse_start.h).
#include <glm/vec2.hpp>

#include <vector>

namespace paver {

class DisplacementField {
public:
  // A grid of spacing `cell` covering [lo, hi] with one cell to spare on every side.
  DisplacementField(glm::dvec2 lo, glm::dvec2 hi, double cell);

  void add(glm::dvec2 at, glm::dvec2 value);
  // Normalizes the sums and fills the nodes without samples from their neighbours; call once,
  // after the last add. A field without any sample is zero everywhere.
  void finish();
  glm::dvec2 at(glm::dvec2 p) const;  // outside the grid: the nearest border node's value

private:
  int node(int i, int j) const { return j * nx_ + i; }
  glm::dvec2 origin_;
  double cell_;
  int nx_, ny_;
  std::vector<glm::dvec2> sum_;
  std::vector<double> weight_;
};

}  // namespace paver
