#pragma once
// The surface as the solver sees it: float32 copies of the map M^ (uv), the surface positions,
// curvature and triangles, the point-location grid, and the boundary segments used to bring
// stray particles back. Flat arrays, each one an SSBO on the GPU.
#include "map/surface_map.h"

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <vector>

namespace paver {

// On a map that wraps (a band's seamless map), the vertices and triangles are its MapDomain's (three
// copies of each triangle, in one piece each); positions are wrapped into the period before they
// are located, and a stray is pulled back to its nearest image of the one copy of the boundary.
struct SolverSurface {
  std::vector<glm::vec2> uv;                 // #V map coordinates
  std::vector<glm::vec4> position;           // #V surface positions (w unused: std430 alignment)
  std::vector<float> curvature;              // #V mean curvature |H|
  std::vector<std::int32_t> triangles;       // #F * 3 vertex indices
  float period = 0, period_origin = 0;       // SurfaceMap's: 0 when the map does not wrap
  // Uniform grid (same layout as UvGrid, in float).
  glm::vec2 grid_origin{0};
  float grid_cell_size = 1;
  std::int32_t grid_nx = 0, grid_ny = 0;
  std::vector<std::int32_t> grid_start;      // #cells + 1
  std::vector<std::int32_t> grid_triangles;  // CSR triangle lists
  // Boundary of M^, every loop's segments: segment s joins boundary_segments[s].xy and .zw; a
  // point pulled back onto it is nudged towards the centroid of the boundary triangle on it.
  std::vector<glm::vec4> boundary_segments;  // #B segment ends
  std::vector<glm::vec2> boundary_inward;    // #B centroid of the triangle on segment s
  // The segments binned in the grid's cells (CSR, every cell each segment's box overlaps and one
  // more around): the pull-back searches the cells near a stray, not every segment.
  std::vector<std::int32_t> boundary_grid_start;     // #cells + 1
  std::vector<std::int32_t> boundary_grid_segments;  // CSR segment lists
  float curvature_min = 0, curvature_max = 0;
  glm::vec2 centre{0};                       // O(M^): centre of the map's bounding box (eq. 12)
  // A hash of every array and value above, made once: a GPU solver uploads the surface again
  // only when it changes.
  std::uint64_t fingerprint = 0;
};

SolverSurface make_solver_surface(const SurfaceMap& map);

}  // namespace paver
