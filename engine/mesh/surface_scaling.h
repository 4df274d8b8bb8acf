#pragma once
// Rescales a parameterization so its 2D area equals the surface's 3D area (private to engine/).
#include "mesh/surface_mesh.h"

#include <glm/vec2.hpp>

#include <vector>

namespace paver::detail {

double uv_area(const SurfaceMesh& mesh, const std::vector<glm::dvec2>& uv);
// The map applied: uv -> (uv - centre) * scale (identity when uv has no area).
struct UvRescale {
  glm::dvec2 centre{0};
  double scale = 1;
  glm::dvec2 operator()(glm::dvec2 p) const { return (p - centre) * scale; }
};
UvRescale scale_to_surface_area(const SurfaceMesh& mesh, std::vector<glm::dvec2>& uv);

}  // namespace paver::detail
