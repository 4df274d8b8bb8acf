#include "map/boundary_index.h"

#include "core/cell_grid.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <limits>

namespace paver {

namespace {

// Cells at least `reach` wide over the mesh's box grown by it, and no smaller than a quarter of
// the longest boundary segment.
CellGrid boundary_grid(const SurfaceMesh& mesh, const std::vector<glm::ivec2>& segments, double reach) {
  const auto& pos = mesh.positions;
  double longest = 0;
  for (const glm::ivec2& s : segments) longest = std::max(longest, glm::length(pos[s.y] - pos[s.x]));
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (const glm::dvec3& p : pos) lo = glm::min(lo, p), hi = glm::max(hi, p);
  if (pos.empty()) lo = hi = glm::dvec3(0);
  return CellGrid(lo - glm::dvec3(reach), hi + glm::dvec3(reach), std::max(reach, 0.25 * longest));
}

}  // namespace

BoundaryIndex::BoundaryIndex(const SurfaceMesh& mesh, double reach)
    : mesh_(mesh),
      segments_(boundary_segments(mesh)),
      reach_(reach > 0 ? reach : 1),
      grid_(boundary_grid(mesh, segments_, reach_)) {
  const auto& pos = mesh.positions;
  for (int i = 0; i < int(segments_.size()); ++i) {
    const glm::dvec3 a = pos[segments_[i].x], b = pos[segments_[i].y];
    const glm::ivec3 c0 = grid_.cell_of(glm::min(a, b)), c1 = grid_.cell_of(glm::max(a, b));
    for (int z = c0.z; z <= c1.z; ++z)
      for (int y = c0.y; y <= c1.y; ++y)
        for (int x = c0.x; x <= c1.x; ++x) buckets_[CellGrid::key({x, y, z})].push_back(i);
  }
}

BoundaryIndex::Nearest BoundaryIndex::nearest(const glm::dvec3& p) const {
  const auto& pos = mesh_.positions;
  Nearest best{reach_, p};
  grid_.for_each_key_around(p, [&](std::uint64_t key) {
    const auto it = buckets_.find(key);
    if (it == buckets_.end()) return;
    for (int i : it->second) {
      const glm::dvec3 a = pos[segments_[i].x], ab = pos[segments_[i].y] - a;
      const double len2 = glm::dot(ab, ab);
      const double t = len2 > 0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
      const glm::dvec3 q = a + t * ab;
      const double d = glm::length(p - q);
      if (d < best.distance) best = {d, q};
    }
  });
  return best;
}

}  // namespace paver
