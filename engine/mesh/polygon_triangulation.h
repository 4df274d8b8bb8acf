#pragma once
// Polygons to triangles, keeping each polygon's orientation: ear clipping in the polygon's
// best-fit plane, so that non-convex polygons do not fold over. Degenerate polygons (fewer than 3
// distinct vertices, or less area than `min_area`) are left out and counted.
#include <glm/vec3.hpp>

#include <vector>

namespace paver {

struct Triangulation {
  std::vector<glm::ivec3> triangles;
  int degenerate = 0;  // polygons, or ear-clipped pieces of them, left out
};

// `polygons` index `positions` (checked by the caller).
Triangulation triangulate(const std::vector<glm::dvec3>& positions, const std::vector<std::vector<int>>& polygons,
                          double min_area);

// Below this area a face counts as degenerate: relative to the size of the referenced geometry.
double degenerate_area(const std::vector<glm::dvec3>& positions, const std::vector<std::vector<int>>& polygons);

}  // namespace paver
