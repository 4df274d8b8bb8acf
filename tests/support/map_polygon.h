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
