#pragma once
// The surface's boundary polylines (all loops) in 3D, its segments bucketed in cubic cells, for nearest-point
// queries within a reach: which elements cross the boundary, and how far the adaptive pattern's
// particles must stay from it.
#include "core/cell_grid.h"
#include "mesh/surface_mesh.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace paver {

class BoundaryIndex {
public:
  // Queries are exact within `reach` of the boundary (> 0); the cells are never smaller than a
  // quarter of the longest boundary segment, so a segment touches only a few of them.
  BoundaryIndex(const SurfaceMesh& mesh, double reach);

  struct Nearest {
    double distance;   // to the nearest boundary point; `reach` when none lies within it
    glm::dvec3 point;  // that point (meaningful only when distance < reach)
  };
  Nearest nearest(const glm::dvec3& p) const;
  double reach() const { return reach_; }

private:
  const SurfaceMesh& mesh_;
  std::vector<glm::ivec2> segments_;
  double reach_;
  CellGrid grid_;
  std::unordered_map<std::uint64_t, std::vector<int>> buckets_;  // cell -> boundary segments
};

}  // namespace paver
