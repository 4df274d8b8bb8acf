#include "map/boundary_index.h"

#include "elements/cell_grid.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <limits>

namespace paver {

namespace {

// Cells at least `reach` wide over the mesh's box grown by it, and no smaller than a quarter of
// the longest boundary segment.
CellGrid boundary_grid(const SurfaceMesh& mesh, double reach) {
  const auto& loop = mesh.boundary_loop;
  const auto& pos = mesh.positions;
  const int n = int(loop.size());
  double longest = 0;
  for (int i = 0; i < n; ++i) longest = std::max(longest, glm::length(pos[loop[(i + 1) % n]] - pos[loop[i]]));
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (const glm::dvec3& p : pos) lo = glm::min(lo, p), hi = glm::max(hi, p);
  if (pos.empty()) lo = hi = glm::dvec3(0);
  return CellGrid(lo - glm::dvec3(reach), hi + glm::dvec3(reach), std::max(reach, 0.25 * longest));
}

}  // namespace

BoundaryIndex::BoundaryIndex(const SurfaceMesh& mesh, double reach)
    : mesh_(mesh), reach_(reach > 0 ? reach : 1), grid_(boundary_grid(mesh, reach_)) {
  const auto& loop = mesh.boundary_loop;
  const auto& pos = mesh.positions;
  const int n = int(loop.size());
  for (int i = 0; i < n; ++i) {
    const glm::dvec3 a = pos[loop[i]], b = pos[loop[(i + 1) % n]];
    const glm::ivec3 c0 = grid_.cell_of(glm::min(a, b)), c1 = grid_.cell_of(glm::max(a, b));
    for (int z = c0.z; z <= c1.z; ++z)
      for (int y = c0.y; y <= c1.y; ++y)
        for (int x = c0.x; x <= c1.x; ++x) buckets_[CellGrid::key({x, y, z})].push_back(i);
  }
}

BoundaryIndex::Nearest BoundaryIndex::nearest(const glm::dvec3& p) const {
  const auto& loop = mesh_.boundary_loop;
  const auto& pos = mesh_.positions;
  const int n = int(loop.size());
  Nearest best{reach_, p};
  grid_.for_each_key_around(p, [&](std::uint64_t key) {
    const auto it = buckets_.find(key);
    if (it == buckets_.end()) return;
    for (int i : it->second) {
      const glm::dvec3 a = pos[loop[i]], ab = pos[loop[(i + 1) % n]] - a;
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
