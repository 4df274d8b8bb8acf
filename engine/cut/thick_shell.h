#pragma once
// The metal under a pavement: the surface thickened against its normals into a closed solid.
// The top is the surface itself (the stones sit on it), the bottom the surface moved by
// `thickness` against its vertex normals, and a wall joins them along the boundary loop.
#include "mesh/surface_mesh.h"

#include <glm/vec3.hpp>

#include <vector>

namespace paver {

// `normals`: #V unit vertex normals (the map's). Throws InputError when `thickness` is not a
// positive finite number. The result is closed and outward-oriented; where the surface curves
// tighter than `thickness` the bottom folds into itself, which the boolean stage checks.
SurfaceMesh thick_shell(const SurfaceMesh& surface, const std::vector<glm::dvec3>& normals, double thickness);

}  // namespace paver
