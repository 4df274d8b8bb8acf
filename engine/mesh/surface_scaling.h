#pragma once
// Rescales a parameterization so its 2D area equals the surface's 3D area (private to engine/).
#include "mesh/surface_mesh.h"

#include <glm/vec2.hpp>

#include <vector>

namespace paver::detail {

double uv_area(const SurfaceMesh& mesh, const std::vector<glm::dvec2>& uv);
void scale_to_surface_area(const SurfaceMesh& mesh, std::vector<glm::dvec2>& uv);

}  // namespace paver::detail
