#include "surface_pick.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace paver::studio {

std::optional<SurfaceHit> first_hit(const SurfaceMesh& mesh, glm::dvec3 origin, glm::dvec3 direction) {
  std::optional<SurfaceHit> best;
  for (int t = 0; t < mesh.face_count(); ++t) {
    const glm::ivec3 f = mesh.triangles[std::size_t(t)];
    const glm::dvec3 a = mesh.positions[std::size_t(f.x)], b = mesh.positions[std::size_t(f.y)],
                     c = mesh.positions[std::size_t(f.z)];
    // Moller-Trumbore: solve origin + s direction = a + v (b - a) + w (c - a).
    const glm::dvec3 ab = b - a, ac = c - a;
    const glm::dvec3 p = glm::cross(direction, ac);
    const double det = glm::dot(ab, p);
    if (std::abs(det) < 1e-300) continue;  // the ray runs along the triangle's plane
    const glm::dvec3 to_origin = origin - a;
    const double v = glm::dot(to_origin, p) / det;
    if (v < 0 || v > 1) continue;
    const glm::dvec3 q = glm::cross(to_origin, ab);
    const double w = glm::dot(direction, q) / det;
    if (w < 0 || v + w > 1) continue;
    const double s = glm::dot(ac, q) / det;
    if (s <= 0 || (best && s >= best->distance)) continue;
    best = SurfaceHit{t, {1 - v - w, v, w}, s};
  }
  return best;
}

}  // namespace paver::studio
