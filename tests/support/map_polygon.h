#pragma once
// The map's boundary as a polygon in the uv plane, and an independent point-in-polygon test, for
// tests that check the engine's own point location and trimming against something it did not compute.
#include "map/surface_map.h"

#include <glm/vec2.hpp>

#include <vector>

namespace paver::test {

inline std::vector<glm::dvec2> boundary_polygon(const SurfaceMap& map) {
  std::vector<glm::dvec2> polygon;
  for (int v : map.mesh.outer_loop()) polygon.push_back(map.uv[v]);
  return polygon;
}

// Boundary loop `l` (0 the outer one, then the holes) as a polygon in the map.
inline std::vector<glm::dvec2> loop_polygon(const SurfaceMap& map, size_t l) {
  std::vector<glm::dvec2> polygon;
  for (int v : map.mesh.boundary_loops[l]) polygon.push_back(map.uv[v]);
  return polygon;
}

// Twice the signed area (positive counter-clockwise).
inline double signed_area2(const std::vector<glm::dvec2>& polygon) {
  double sum = 0;
  for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++)
    sum += polygon[j].x * polygon[i].y - polygon[i].x * polygon[j].y;
  return sum;
}

// Crossing-number test.
inline bool inside(const std::vector<glm::dvec2>& polygon, glm::dvec2 p) {
  bool in = false;
  for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const glm::dvec2 a = polygon[i], b = polygon[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) in = !in;
  }
  return in;
}

}  // namespace paver::test
