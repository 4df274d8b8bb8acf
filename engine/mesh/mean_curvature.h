#pragma once
// Discrete mean curvature magnitude |H| per vertex from the cotangent Laplace-Beltrami operator
// (Meyer et al. 2003, section 5.1 of the paper): Delta x = 2 H n, with the barycentric vertex area.
// At boundary vertices the operator is not defined; they take the mean of their interior
// neighbours (0 where they have none).
#include "mesh/surface_mesh.h"

#include <vector>

namespace paver {

std::vector<double> mean_curvature(const SurfaceMesh& mesh);  // #V, |H| >= 0, units 1/length

// Area-weighted vertex normals, unit length (#V).
std::vector<glm::dvec3> vertex_normals(const SurfaceMesh& mesh);

}  // namespace paver
