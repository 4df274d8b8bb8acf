#pragma once
// The parameterization as an OBJ any 3D tool opens as a textured mesh: the surface's vertices as
// `v`, the map as `vt`, faces `f a/a b/b c/c`. Written atomically.
#include "mesh/surface_mesh.h"

#include <glm/vec2.hpp>

#include <filesystem>
#include <vector>

namespace paver {

void write_uv_map_obj(const std::filesystem::path& path, const SurfaceMesh& mesh,
                      const std::vector<glm::dvec2>& uv);

}  // namespace paver
