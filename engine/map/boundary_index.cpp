#include "map/boundary_index.h"

#include "elements/cell_grid.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <limits>

namespace paver {

BoundaryIndex::BoundaryIndex(const SurfaceMesh& mesh, double reach) : mesh_(mesh), reach_(reach > 0 ? reach : 1) {
  const auto& loop = mesh.boundary_loop;
  const auto& pos = mesh.positions;
  const int n = int(loop.size());
  double longest = 0;
  for (int i = 0; i < n; ++i) longest = std::max(longest, glm::length(pos[loop[(i + 1) % n]] - pos[loop[i]]));
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (const glm::dvec3& p : pos) lo = glm::min(lo, p), hi = glm::max(hi, p);
  if (pos.empty()) lo = hi = glm::dvec3(0);
  const CellGrid grid(lo - glm::dvec3(reach_), hi + glm::dvec3(reach_), std::max(reach_, 0.25 * longest));
  origin_ = grid.origin;
  cell_ = grid.cell;
  for (int i = 0; i < n; ++i) {
    const glm::dvec3 a = pos[loop[i]], b = pos[loop[(i + 1) % n]];
    const glm::ivec3 c0 = grid.cell_of(glm::min(a, b)), c1 = grid.cell_of(glm::max(a, b));
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
  const glm::dvec3 r = (p - origin_) / cell_;
  const glm::ivec3 c(int(std::floor(r.x)), int(std::floor(r.y)), int(std::floor(r.z)));
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const auto it = buckets_.find(CellGrid::key(c + glm::ivec3(dx, dy, dz)));
        if (it == buckets_.end()) continue;
        for (int i : it->second) {
          const glm::dvec3 a = pos[loop[i]], ab = pos[loop[(i + 1) % n]] - a;
          const double len2 = glm::dot(ab, ab);
          const double t = len2 > 0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
          const glm::dvec3 q = a + t * ab;
          const double d = glm::length(p - q);
          if (d < best.distance) best = {d, q};
        }
      }
  return best;
}

}  // namespace paver
