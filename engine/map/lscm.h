#pragma once
// Least-squares conformal map with a free boundary (Levy et al. 2002), written as the Dirichlet
// energy minus the signed area of the boundary polygon (Mullen et al. 2008), with two boundary
// vertices pinned. Often flip-free and much closer to isometric than a Tutte embedding, so it is
// the preferred start for the bijective map when it is bijective.
#include "mesh/surface_mesh.h"

#include <glm/vec2.hpp>

#include <vector>

namespace paver {

// uv: #V parameter coordinates, scaled so the 2D area equals the 3D area. Not guaranteed
// bijective: check with measure_map() before trusting it.
std::vector<glm::dvec2> lscm(const SurfaceMesh& mesh);

}  // namespace paver
