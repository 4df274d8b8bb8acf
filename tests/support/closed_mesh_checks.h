#pragma once
// Independent checks of a closed triangle mesh, for the subtractive solid's tests: every edge
// shared by exactly two triangles running it in opposite directions (closed, edge-manifold,
// consistently oriented), and its volume by the divergence theorem.
#include "mesh/surface_mesh.h"

#include <glm/geometric.hpp>

#include <cstdint>
#include <map>
#include <utility>

namespace paver::test {

// How many directed edges break the rule (0 for a closed, oriented, edge-manifold mesh).
inline std::size_t unpaired_edges(const SurfaceMesh& m) {
  std::map<std::pair<int, int>, int> directed;
  for (const glm::ivec3& t : m.triangles)
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  std::size_t bad = 0;
  for (const auto& [edge, count] : directed) {
    const auto reverse = directed.find({edge.second, edge.first});
    if (count != 1 || reverse == directed.end() || reverse->second != 1) ++bad;
  }
  return bad;
}

inline double signed_volume(const SurfaceMesh& m) {
  double six_v = 0;
  for (const glm::ivec3& t : m.triangles)
    six_v += glm::dot(m.positions[std::size_t(t.x)], glm::cross(m.positions[std::size_t(t.y)], m.positions[std::size_t(t.z)]));
  return six_v / 6;
}

}  // namespace paver::test
