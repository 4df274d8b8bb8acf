#pragma once
// A flat surface's map is its projection onto its plane: no distortion at all, so a lattice laid
// on it is as regular on the surface as in the plane, whatever holes it has. The descent would
// reach the same map up to a rotation, except where holes are closed with invented triangles for
// it (hole_patches.h), which bend the rows beside a window. The plane's u axis follows the world
// axis that lies most in it (x, then y, then z), so a wall's rows run level and a floor's along x;
// a surface taller than wide is turned a quarter, so its rows run up it (planar_map.cpp says why).
#include "map/bijective_map.h"
#include "mesh/surface_mesh.h"

#include <optional>

namespace paver {

// How far a vertex may lie off the best plane, as a fraction of the surface's largest extent, for
// the surface to count as flat.
inline constexpr double kFlatTolerance = 1e-4;

// The projection of a flat surface, scaled and centred as every map is; nothing when the surface
// is not flat (above) or the projection is not bijective.
std::optional<Parameterization> planar_parameterization(const SurfaceMesh& mesh);

}  // namespace paver
