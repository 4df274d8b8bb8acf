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

std::vector<glm::ivec2> boundary_segments(const SurfaceMesh& mesh) {
  std::vector<glm::ivec2> segments;
  segments.reserve(boundary_vertex_count(mesh));
  for (const std::vector<int>& loop : mesh.boundary_loops)
    for (size_t k = 0; k < loop.size(); ++k) segments.emplace_back(loop[k], loop[(k + 1) % loop.size()]);
  return segments;
}

double loop_length(const std::vector<glm::dvec3>& positions, const std::vector<int>& loop) {
  double length = 0;
  for (std::size_t k = 0; k < loop.size(); ++k) length += glm::length(positions[loop[(k + 1) % loop.size()]] - positions[loop[k]]);
  return length;
}

double boundary_length(const SurfaceMesh& mesh) {
  double length = 0;
  for (const glm::ivec2& s : boundary_segments(mesh)) length += glm::length(mesh.positions[s.y] - mesh.positions[s.x]);
  return length;
}

int boundary_vertex_count(const SurfaceMesh& mesh) {
  size_t count = 0;
  for (const std::vector<int>& loop : mesh.boundary_loops) count += loop.size();
  return static_cast<int>(count);
}

}  // namespace paver
