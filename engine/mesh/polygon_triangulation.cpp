#include "mesh/polygon_triangulation.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace paver {
namespace {

double triangle_area(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  return 0.5 * glm::length(glm::cross(b - a, c - a));
}

double cross2(const glm::dvec2& a, const glm::dvec2& b) { return a.x * b.y - a.y * b.x; }

bool has_repeated_vertex(const std::vector<int>& polygon) {
  if (polygon.size() <= 8) {
    for (size_t i = 0; i < polygon.size(); ++i)
      for (size_t j = i + 1; j < polygon.size(); ++j)
        if (polygon[i] == polygon[j]) return true;
    return false;
  }
  std::vector<int> sorted = polygon;
  std::sort(sorted.begin(), sorted.end());
  return std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end();
}

// Splits a polygon (3+ distinct vertices, non-zero Newell area) into triangles by ear clipping in
// its best-fit plane, keeping its orientation; falls back to a fan from the remaining vertices
// when no ear is left (self-intersecting polygons). Returns how many zero-area triangles it had
// to leave out.
int triangulate_polygon(const std::vector<glm::dvec3>& positions, const std::vector<int>& polygon,
                        const glm::dvec3& newell, double min_area, std::vector<glm::ivec3>& out) {
  const int k = int(polygon.size());
  const glm::dvec3 n = glm::normalize(newell);
  const glm::dvec3 helper = std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  const glm::dvec3 u = glm::normalize(glm::cross(helper, n));
  const glm::dvec3 v = glm::cross(n, u);  // (u, v, n) right-handed: the polygon runs counter-clockwise
  const glm::dvec3& origin = positions[polygon[0]];
  std::vector<glm::dvec2> q(k);
  for (int i = 0; i < k; ++i) {
    const glm::dvec3 d = positions[polygon[i]] - origin;
    q[i] = glm::dvec2(glm::dot(d, u), glm::dot(d, v));
  }
  std::vector<int> prev(k), next(k);
  for (int i = 0; i < k; ++i) {
    prev[i] = (i + k - 1) % k;
    next[i] = (i + 1) % k;
  }

  int dropped = 0;
  auto emit = [&](int a, int b, int c) {
    const glm::ivec3 t(polygon[a], polygon[b], polygon[c]);
    if (triangle_area(positions[t.x], positions[t.y], positions[t.z]) < min_area) ++dropped;
    else out.push_back(t);
  };
  // An ear: a convex corner (with more than the degenerate-area tolerance) whose triangle holds no
  // other remaining vertex, on its edges included.
  auto is_ear = [&](int a, int b, int c) {
    if (0.5 * cross2(q[b] - q[a], q[c] - q[a]) <= min_area) return false;
    for (int r = next[c]; r != a; r = next[r]) {
      if (cross2(q[b] - q[a], q[r] - q[a]) >= 0 && cross2(q[c] - q[b], q[r] - q[b]) >= 0 &&
          cross2(q[a] - q[c], q[r] - q[c]) >= 0)
        return false;
    }
    return true;
  };

  int remaining = k, current = 0, misses = 0;
  while (remaining > 3 && misses < remaining) {
    const int a = prev[current], c = next[current];
    if (is_ear(a, current, c)) {
      out.push_back(glm::ivec3(polygon[a], polygon[current], polygon[c]));
      next[a] = c;
      prev[c] = a;
      --remaining;
      misses = 0;
      current = c;
    } else {
      current = c;
      ++misses;
    }
  }
  for (int b = next[current]; next[b] != current; b = next[b]) emit(current, b, next[b]);
  return dropped;
}

}  // namespace

Triangulation triangulate(const std::vector<glm::dvec3>& positions, const std::vector<std::vector<int>>& polygons,
                          double global_min_area) {
  Triangulation result;
  result.triangles.reserve(polygons.size());
  for (const std::vector<int>& polygon : polygons) {
    if (polygon.size() < 3 || has_repeated_vertex(polygon)) {
      ++result.degenerate;
      continue;
    }
    // Degenerate relative to the whole part and to the face itself: one far-away vertex (a large
    // bounding box) must not make the ordinary faces elsewhere count as degenerate.
    double longest_edge2 = 0;
    for (size_t i = 0; i < polygon.size(); ++i) {
      const glm::dvec3 e = positions[polygon[(i + 1) % polygon.size()]] - positions[polygon[i]];
      longest_edge2 = std::max(longest_edge2, glm::dot(e, e));
    }
    const double min_area = std::min(global_min_area, 1e-12 * longest_edge2);
    if (polygon.size() == 3) {
      const glm::ivec3 t(polygon[0], polygon[1], polygon[2]);
      if (triangle_area(positions[t.x], positions[t.y], positions[t.z]) < min_area) ++result.degenerate;
      else result.triangles.push_back(t);
      continue;
    }
    // Newell's normal: twice the vector area; robust for non-planar and non-convex polygons.
    glm::dvec3 newell(0.0);
    const glm::dvec3& origin = positions[polygon[0]];
    for (size_t i = 0; i < polygon.size(); ++i)
      newell += glm::cross(positions[polygon[i]] - origin, positions[polygon[(i + 1) % polygon.size()]] - origin);
    if (0.5 * glm::length(newell) < min_area) {
      ++result.degenerate;
      continue;
    }
    result.degenerate += triangulate_polygon(positions, polygon, newell, min_area, result.triangles);
  }
  return result;
}

double degenerate_area(const std::vector<glm::dvec3>& positions, const std::vector<std::vector<int>>& polygons) {
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (const std::vector<int>& polygon : polygons)
    for (int index : polygon) {
      lo = glm::min(lo, positions[index]);
      hi = glm::max(hi, positions[index]);
    }
  const double diagonal = polygons.empty() ? 0.0 : glm::length(hi - lo);
  return 1e-12 * diagonal * diagonal;
}

}  // namespace paver
