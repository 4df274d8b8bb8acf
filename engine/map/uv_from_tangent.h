#pragma once
// The least-squares inverse of one map triangle's affine map: the uv displacement that produces a
// given 3D tangent displacement on the surface. Refill steps out from elements with it; the
// adaptive pattern moves its particles with it.
#include "map/surface_map.h"

#include <glm/geometric.hpp>
#include <glm/mat2x2.hpp>

#include <array>
#include <cmath>

namespace paver {

struct UvFromTangent {
  glm::dvec3 ju{0.0}, jv{0.0};  // dP/du, dP/dv
  glm::dmat2 inverse_normal{0.0};

  // Zero for a degenerate triangle (the displacement maps to no move).
  UvFromTangent(const SurfaceMap& map, int t) {
    const glm::ivec3 tri = map.mesh.triangles[t];
    const std::array<glm::dvec2, 3> corner = triangle_uv(map, t);
    const glm::dmat2 uv_edges(corner[1] - corner[0], corner[2] - corner[0]);
    if (std::abs(glm::determinant(uv_edges)) == 0) return;
    const glm::dmat2 to_bary = glm::inverse(uv_edges);
    const glm::dvec3 p0 = map.mesh.positions[tri.x];
    const glm::dvec3 e1 = map.mesh.positions[tri.y] - p0, e2 = map.mesh.positions[tri.z] - p0;
    ju = e1 * to_bary[0][0] + e2 * to_bary[0][1];
    jv = e1 * to_bary[1][0] + e2 * to_bary[1][1];
    const glm::dmat2 normal(glm::dot(ju, ju), glm::dot(ju, jv), glm::dot(jv, ju), glm::dot(jv, jv));
    if (std::abs(glm::determinant(normal)) > 0) inverse_normal = glm::inverse(normal);
  }
  glm::dvec2 operator()(const glm::dvec3& step) const {
    return inverse_normal * glm::dvec2(glm::dot(ju, step), glm::dot(jv, step));
  }
};

}  // namespace paver
