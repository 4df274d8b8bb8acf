#pragma once
// Point location in the 2D map M^ (the paper's hash table, section 4.2): a uniform grid over the
// triangles' bounding box, each cell listing the triangles whose bounding boxes overlap it.
// Stored as flat arrays (CSR) so it uploads to the GPU unchanged.
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace paver {

struct UvGrid {
  glm::dvec2 origin{0};               // lower-left corner of the grid
  double cell_size = 1;               // square cells
  int nx = 0, ny = 0;                 // cells along u and v
  std::vector<std::int32_t> cell_start;      // #cells + 1: triangles of cell c are
  std::vector<std::int32_t> cell_triangles;  // cell_triangles[cell_start[c] .. cell_start[c+1])
};

// Builds the grid with about `triangles_per_cell` triangles per cell on average.
UvGrid build_uv_grid(const std::vector<glm::dvec2>& uv, const std::vector<glm::ivec3>& triangles,
                     double triangles_per_cell = 2.0);

// Barycentric coordinates of p in triangle (a, b, c).
glm::dvec3 barycentric(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b, glm::dvec2 c);

// The triangle containing p (with a small tolerance for points on edges), or -1 when p is outside
// the map. `bary` receives p's barycentric coordinates in it, clamped to the triangle.
int locate(const UvGrid& grid, const std::vector<glm::dvec2>& uv,
           const std::vector<glm::ivec3>& triangles, glm::dvec2 p, glm::dvec3& bary);

}  // namespace paver
