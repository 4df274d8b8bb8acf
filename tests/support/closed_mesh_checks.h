#pragma once
// Independent checks of a closed triangle mesh, for the subtractive solid's tests: every edge
// shared by exactly two triangles running it in opposite directions (closed, edge-manifold,
// consistently oriented), and its volume by the divergence theorem.
#include "mesh/surface_mesh.h"

#include <glm/geometric.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

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

// Problems the mesh would have once written as 3MF, whose coordinates lib3mf prints with six
// decimals: vertices that print as one point, and triangles that print with zero area.
struct Printed3mfProblems {
  std::size_t merged_vertices = 0, zero_area_triangles = 0;
};
inline Printed3mfProblems printed_3mf_problems(const SurfaceMesh& m) {
  Printed3mfProblems problems;
  std::vector<glm::dvec3> printed;
  std::map<std::array<long long, 3>, int> seen;
  for (const glm::dvec3& p : m.positions) {
    const glm::dvec3 q(std::round(double(float(p.x)) * 1e6), std::round(double(float(p.y)) * 1e6),
                       std::round(double(float(p.z)) * 1e6));
    problems.merged_vertices += ++seen[{(long long)q.x, (long long)q.y, (long long)q.z}] > 1;
    printed.push_back(q);
  }
  for (const glm::ivec3& t : m.triangles) {
    const glm::dvec3 a = printed[std::size_t(t.x)], b = printed[std::size_t(t.y)], c = printed[std::size_t(t.z)];
    problems.zero_area_triangles += glm::cross(b - a, c - a) == glm::dvec3(0);
  }
  return problems;
}

inline double signed_volume(const SurfaceMesh& m) {
  double six_v = 0;
  for (const glm::ivec3& t : m.triangles)
    six_v += glm::dot(m.positions[std::size_t(t.x)], glm::cross(m.positions[std::size_t(t.y)], m.positions[std::size_t(t.z)]));
  return six_v / 6;
}

}  // namespace paver::test
