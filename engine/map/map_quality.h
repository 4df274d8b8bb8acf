#pragma once
// How good and how valid a parameterization is: flipped triangles, boundary self-overlaps and
// the distortion of each triangle's Jacobian (singular values s1 >= s2 of the 3D -> 2D map).
#include "mesh/surface_mesh.h"

#include <glm/vec2.hpp>

#include <vector>

namespace paver {

struct MapQuality {
  int flipped_triangles = 0;             // signed 2D area <= 0
  int boundary_intersections = 0;        // pairs of boundary edges (of any loops) without a common vertex that cross
  double stretch_mean = 0;               // area-weighted mean of s1/s2 (1 = conformal)
  double stretch_max = 0;                // max of s1/s2 over triangles
  double area_ratio_min = 0;             // min of (2D area / 3D area), after scaling to equal total area
  double area_ratio_max = 0;
  double area_distortion_mean = 0;       // area-weighted mean of |2D area / 3D area - 1|

  bool bijective() const { return flipped_triangles == 0 && boundary_intersections == 0; }
};

MapQuality measure_map(const SurfaceMesh& mesh, const std::vector<glm::dvec2>& uv);

// Number of pairs of non-adjacent edges of the closed polygon `loop` (indices into uv) that
// intersect. Uses a uniform grid, so it is linear in the loop length for even edge lengths.
int count_loop_self_intersections(const std::vector<int>& loop, const std::vector<glm::dvec2>& uv);

// Number of pairs of segments (vertex index pairs into uv) without a common vertex that intersect:
// the crossings between and within all boundary loops.
int count_segment_intersections(const std::vector<glm::ivec2>& segments, const std::vector<glm::dvec2>& uv);

// Number of triangles whose signed area in uv is not positive.
int count_flipped_triangles(const SurfaceMesh& mesh, const std::vector<glm::dvec2>& uv);

}  // namespace paver
