#pragma once
// Where a ray from the 3D view's camera first meets the surface: the triangle and barycentric
// coordinates, from which the map point follows (map_point, eq. 1). A stone dragged in the 3D view
// is dropped where the cursor's ray meets the surface.
#include "mesh/surface_mesh.h"

#include <glm/vec3.hpp>

#include <optional>

namespace paver::studio {

struct SurfaceHit {
  int triangle = -1;
  glm::dvec3 bary{0};    // weights of the triangle's corners
  double distance = 0;   // along the ray, in units of |direction|
};

// The nearest hit in front of `origin` along `direction`, either side of a triangle; none when the
// ray misses the surface. Tests every triangle (a drop is one ray, not one per frame).
std::optional<SurfaceHit> first_hit(const SurfaceMesh& mesh, glm::dvec3 origin, glm::dvec3 direction);

}  // namespace paver::studio
