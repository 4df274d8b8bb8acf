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

// The closed solid between `surface` (its top) and a copy of it with vertex v at `bottom[v]`
// (#V), joined by walls along the boundary: what thick_shell and a ring's shell (cut/finger_side.h)
// both are. Outward-oriented when the bottom lies behind the top, against its normals.
SurfaceMesh shell_between(const SurfaceMesh& surface, const std::vector<glm::dvec3>& bottom);

}  // namespace paver
