#pragma once
// The checks every generated surface must pass before it is written, and its statistics.
#include "mesh_building.h"

#include <glm/vec3.hpp>

#include <string_view>

namespace paver::assetgen {

struct Stats {
  int vertices = 0;
  int faces = 0;
  double min_angle_deg = 180.0;
  double edge_mean = 0.0;
  double edge_cv = 0.0;  // standard deviation / mean of edge lengths
  glm::dvec3 lo{0.0}, hi{0.0};
};

// Topology through the engine's make_surface (finite, non-degenerate, manifold, connected,
// consistently oriented, no handles), with any repair it makes counted as a failure; then what is
// particular to the assets: `boundary_loops` loops, normals on the `outward` side and the minimum
// angle. Throws std::runtime_error ("name: what is wrong") on failure.
Stats check(std::string_view name, const Mesh& m, const Outward& outward, int boundary_loops = 1);

}  // namespace paver::assetgen
