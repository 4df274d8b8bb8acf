#include "mesh/surface_mesh.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <limits>

namespace paver {

double surface_area(const SurfaceMesh& mesh) {
  double area = 0.0;
  for (const glm::ivec3& t : mesh.triangles) {
    const glm::dvec3& a = mesh.positions[t.x];
    area += 0.5 * glm::length(glm::cross(mesh.positions[t.y] - a, mesh.positions[t.z] - a));
  }
  return area;
}

double bounding_box_diagonal(const SurfaceMesh& mesh) {
  if (mesh.positions.empty()) return 0.0;
  glm::dvec3 lo(std::numeric_limits<double>::infinity());
  glm::dvec3 hi(-std::numeric_limits<double>::infinity());
  for (const glm::dvec3& p : mesh.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return glm::length(hi - lo);
}

}  // namespace paver
