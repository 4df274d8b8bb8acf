#pragma once
// Tutte embedding with mean-value weights (Floater 2003): the boundary loop is pinned to a circle
// by arc length and every interior vertex is a convex combination of its neighbours. Positive
// weights and a convex boundary make the map bijective by construction, which is why it is
// the fall-back start for the bijective map.
#include "mesh/surface_mesh.h"

#include <glm/vec2.hpp>

#include <vector>

namespace paver {

// uv: #V parameter coordinates; the circle has the surface's area (radius sqrt(A / pi)).
std::vector<glm::dvec2> tutte_embedding(const SurfaceMesh& mesh);

}  // namespace paver
