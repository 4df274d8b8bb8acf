#pragma once
// Small per-triangle helpers shared by the parameterizers (private to engine/).
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>

namespace paver::detail {

// The triangle laid flat isometrically: corner 0 at the origin, corner 1 on +x.
inline std::array<glm::dvec2, 3> flatten_triangle(const glm::dvec3& p0, const glm::dvec3& p1,
                                                  const glm::dvec3& p2) {
  const glm::dvec3 e1 = p1 - p0, e2 = p2 - p0;
  const double l1 = glm::length(e1);
  const double x2 = glm::dot(e2, e1) / l1;
  const double y2 = glm::length(glm::cross(e1, e2)) / l1;
  return {glm::dvec2(0, 0), glm::dvec2(l1, 0), glm::dvec2(x2, y2)};
}

// cot of the angle at corner `at` of a 3D triangle (a, b, c are the corners in order, at = 0..2).
inline double cotangent(const glm::dvec3& apex, const glm::dvec3& q, const glm::dvec3& r) {
  const glm::dvec3 u = q - apex, v = r - apex;
  const double s = glm::length(glm::cross(u, v));
  return glm::dot(u, v) / std::max(s, 1e-300);
}

inline double cross2(const glm::dvec2& a, const glm::dvec2& b) { return a.x * b.y - a.y * b.x; }

inline double signed_area(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
  return 0.5 * cross2(b - a, c - a);
}

inline double triangle_area(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  return 0.5 * glm::length(glm::cross(b - a, c - a));
}

// The point of segment ab nearest p.
inline glm::dvec3 closest_point_on_segment(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 ab = b - a;
  const double t = glm::dot(p - a, ab) / std::max(glm::dot(ab, ab), 1e-300);
  return a + std::clamp(t, 0.0, 1.0) * ab;
}

// The point of triangle abc nearest p: p's foot on the plane when it falls inside, else the
// nearest point of the three sides (where the nearest point of a triangle lies when the foot is out).
inline glm::dvec3 closest_point_on_triangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                                            const glm::dvec3& c) {
  const glm::dvec3 n = glm::cross(b - a, c - a);
  const double nn = glm::dot(n, n);
  if (nn > 1e-300) {
    const glm::dvec3 foot = p - (glm::dot(p - a, n) / nn) * n;
    if (glm::dot(glm::cross(b - a, foot - a), n) >= 0 && glm::dot(glm::cross(c - b, foot - b), n) >= 0 &&
        glm::dot(glm::cross(a - c, foot - c), n) >= 0)
      return foot;
  }
  glm::dvec3 best = closest_point_on_segment(p, a, b);
  for (const glm::dvec3& q : {closest_point_on_segment(p, b, c), closest_point_on_segment(p, c, a)})
    if (glm::dot(q - p, q - p) < glm::dot(best - p, best - p)) best = q;
  return best;
}

}  // namespace paver::detail
