#pragma once
// Lifting 2D points to the surface (eq. 1-3): locate each point's triangle in M^ and interpolate
// position, normal and curvature barycentrically. Called every solver iteration: the output
// arrays are sized by the caller once and reused; the call allocates nothing and runs in parallel.
#include "map/surface_map.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <span>
#include <vector>

namespace paver {

struct LiftedPoints {
  std::vector<int> triangle;           // containing triangle, -1 when the point is outside M^
  std::vector<glm::dvec3> position;    // P = g^-1(p), eq. 2
  std::vector<glm::dvec3> normal;      // unit normal, barycentric blend of vertex normals
  std::vector<double> curvature;       // kappa(P), eq. 3 (not normalised)

  void resize(std::size_t n);
  std::size_t size() const { return triangle.size(); }
};

// Lifts points[i] into out[i] for every i; out must already have points.size() entries.
// Returns the number of points outside the map (their triangle is -1, other fields untouched).
int lift_points(const SurfaceMap& map, std::span<const glm::dvec2> points, LiftedPoints& out);

// g(P) for a point given by its triangle and barycentric coordinates (eq. 1).
glm::dvec2 map_point(const SurfaceMap& map, int triangle, glm::dvec3 bary);

}  // namespace paver
