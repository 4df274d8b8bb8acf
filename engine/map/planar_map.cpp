#include "map/planar_map.h"

#include "mesh/surface_scaling.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace paver {

std::optional<Parameterization> planar_parameterization(const SurfaceMesh& mesh) {
  if (mesh.vertex_count() < 3 || mesh.face_count() == 0 || mesh.boundary_loops.empty()) return std::nullopt;
  // The plane: the area-weighted normal (the faces' winding) through the area-weighted centre.
  glm::dvec3 normal(0), centre(0);
  double area = 0;
  for (const glm::ivec3& t : mesh.triangles) {
    const glm::dvec3 a = mesh.positions[t.x], b = mesh.positions[t.y], c = mesh.positions[t.z];
    const glm::dvec3 twice = glm::cross(b - a, c - a);
    normal += twice;
    const double w = 0.5 * glm::length(twice);
    centre += w * (a + b + c) / 3.0;
    area += w;
  }
  if (!(glm::length(normal) > 0) || !(area > 0)) return std::nullopt;
  normal = glm::normalize(normal);
  centre /= area;
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
  for (const glm::dvec3& p : mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  for (const glm::dvec3& p : mesh.positions)
    if (std::abs(glm::dot(p - centre, normal)) > kFlatTolerance * extent) return std::nullopt;

  // u: the world axis that lies most in the plane (the first of equals); v completes a right-handed
  // frame with the normal, so the faces keep their winding in the map.
  glm::dvec3 u(0);
  for (int axis = 0; axis < 3; ++axis) {
    glm::dvec3 e(0);
    e[axis] = 1;
    const glm::dvec3 in_plane = e - glm::dot(e, normal) * normal;
    if (glm::length(in_plane) > glm::length(u) * (1 + 1e-9)) u = in_plane;
  }
  u = glm::normalize(u);
  glm::dvec3 v = glm::cross(normal, u);
  // A surface taller than wide is turned a quarter (its rows then run up it): the lattice is laid
  // over the map's box in cell coordinates, which a tall box swells by its height over D times
  // (a strip 1000 long took 5.7e7 lattice positions), and a wide one does not.
  double u_lo = std::numeric_limits<double>::infinity(), u_hi = -u_lo, v_lo = u_lo, v_hi = -u_lo;
  for (const glm::dvec3& p : mesh.positions) {
    u_lo = std::min(u_lo, glm::dot(p, u)), u_hi = std::max(u_hi, glm::dot(p, u));
    v_lo = std::min(v_lo, glm::dot(p, v)), v_hi = std::max(v_hi, glm::dot(p, v));
  }
  if (v_hi - v_lo > u_hi - u_lo) std::swap(u, v), v = -v;

  Parameterization result;
  result.uv.reserve(mesh.vertex_count());
  for (const glm::dvec3& p : mesh.positions) result.uv.emplace_back(glm::dot(p - centre, u), glm::dot(p - centre, v));
  detail::scale_to_surface_area(mesh, result.uv);
  result.quality = measure_map(mesh, result.uv);
  if (!result.quality.bijective()) return std::nullopt;
  result.report.planar = true;
  result.report.start_used = MapStart::Auto;
  return result;
}

}  // namespace paver
