#include "map/map_quality.h"

#include "mesh/triangle_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace paver {
namespace {

int orientation(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
  const double v = detail::cross2(b - a, c - a);
  return (v > 0) - (v < 0);
}

bool on_segment(glm::dvec2 a, glm::dvec2 b, glm::dvec2 p) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

bool segments_intersect(glm::dvec2 p1, glm::dvec2 p2, glm::dvec2 q1, glm::dvec2 q2) {
  const int o1 = orientation(p1, p2, q1), o2 = orientation(p1, p2, q2);
  const int o3 = orientation(q1, q2, p1), o4 = orientation(q1, q2, p2);
  if (o1 != o2 && o3 != o4) return true;
  if (o1 == 0 && on_segment(p1, p2, q1)) return true;
  if (o2 == 0 && on_segment(p1, p2, q2)) return true;
  if (o3 == 0 && on_segment(q1, q2, p1)) return true;
  if (o4 == 0 && on_segment(q1, q2, p2)) return true;
  return false;
}

}  // namespace

int count_flipped_triangles(const SurfaceMesh& mesh, const std::vector<glm::dvec2>& uv) {
  int flipped = 0;
  for (const auto& t : mesh.triangles)
    if (!(detail::signed_area(uv[t.x], uv[t.y], uv[t.z]) > 0)) ++flipped;
  return flipped;
}

int count_segment_intersections(const std::vector<glm::ivec2>& segments, const std::vector<glm::dvec2>& uv) {
  const int n = static_cast<int>(segments.size());
  if (n < 2) return 0;
  glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  double total = 0;
  for (const glm::ivec2& s : segments) {
    const glm::dvec2 p = uv[s.x], q = uv[s.y];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(q.x) || !std::isfinite(q.y))
      return n;  // a broken map overlaps itself
    lo = glm::min(lo, glm::min(p, q)), hi = glm::max(hi, glm::max(p, q));
    total += glm::length(q - p);
  }
  // Cells about one average edge long: each edge touches a few cells, each cell holds a few edges.
  const double cell = std::max(total / n, 1e-300);
  const int nx = std::clamp(int((hi.x - lo.x) / cell) + 1, 1, 4 * n);
  const int ny = std::clamp(int((hi.y - lo.y) / cell) + 1, 1, 4 * n);
  const double sx = nx / std::max(hi.x - lo.x, 1e-300), sy = ny / std::max(hi.y - lo.y, 1e-300);
  auto cell_of = [&](glm::dvec2 p) {
    return glm::ivec2(std::clamp(int((p.x - lo.x) * sx), 0, nx - 1),
                      std::clamp(int((p.y - lo.y) * sy), 0, ny - 1));
  };
  // Counting sort of (cell, edge) pairs into CSR buckets.
  std::vector<int> start(size_t(nx) * ny + 1, 0);
  auto for_cells = [&](int e, auto&& visit) {
    const glm::dvec2 a = uv[segments[e].x], b = uv[segments[e].y];
    const glm::ivec2 c0 = cell_of(glm::min(a, b)), c1 = cell_of(glm::max(a, b));
    for (int y = c0.y; y <= c1.y; ++y)
      for (int x = c0.x; x <= c1.x; ++x) visit(size_t(y) * nx + x);
  };
  for (int e = 0; e < n; ++e) for_cells(e, [&](size_t c) { ++start[c + 1]; });
  for (size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
  std::vector<int> fill(start.begin(), start.end() - 1), edges(start.back());
  for (int e = 0; e < n; ++e) for_cells(e, [&](size_t c) { edges[fill[c]++] = e; });

  int count = 0;
  for (size_t c = 0; c + 1 < start.size(); ++c) {
    for (int i = start[c]; i < start[c + 1]; ++i) {
      for (int j = i + 1; j < start[c + 1]; ++j) {
        const glm::ivec2 s = segments[edges[i]], t = segments[edges[j]];
        if (s.x == t.x || s.x == t.y || s.y == t.x || s.y == t.y) continue;  // neighbours share a vertex
        const glm::dvec2 p1 = uv[s.x], p2 = uv[s.y], q1 = uv[t.x], q2 = uv[t.y];
        if (!segments_intersect(p1, p2, q1, q2)) continue;
        // A pair may share several cells: count it in the first cell both edges touch.
        const glm::ivec2 first = glm::max(cell_of(glm::min(p1, p2)), cell_of(glm::min(q1, q2)));
        if (size_t(first.y) * nx + first.x == c) ++count;
      }
    }
  }
  return count;
}

int count_loop_self_intersections(const std::vector<int>& loop, const std::vector<glm::dvec2>& uv) {
  if (loop.size() < 4) return 0;
  std::vector<glm::ivec2> segments;
  segments.reserve(loop.size());
  for (size_t k = 0; k < loop.size(); ++k) segments.emplace_back(loop[k], loop[(k + 1) % loop.size()]);
  return count_segment_intersections(segments, uv);
}

MapQuality measure_map(const SurfaceMesh& mesh, const std::vector<glm::dvec2>& uv) {
  MapQuality q;
  q.flipped_triangles = count_flipped_triangles(mesh, uv);
  q.boundary_intersections = count_segment_intersections(boundary_segments(mesh), uv);
  double area3 = 0, area2 = 0;
  for (const auto& t : mesh.triangles) {
    area3 += detail::triangle_area(mesh.positions[t.x], mesh.positions[t.y], mesh.positions[t.z]);
    area2 += std::abs(detail::signed_area(uv[t.x], uv[t.y], uv[t.z]));
  }
  const double normalise = area2 > 0 ? area3 / area2 : 1;
  q.area_ratio_min = std::numeric_limits<double>::infinity();
  double weighted_stretch = 0, weighted_area = 0;
  for (const auto& t : mesh.triangles) {
    const auto flat = detail::flatten_triangle(mesh.positions[t.x], mesh.positions[t.y], mesh.positions[t.z]);
    const double a3 = 0.5 * flat[1].x * flat[2].y;
    if (!(a3 > 0)) continue;
    // Jacobian J = [u1-u0, u2-u0] * [x1-x0, x2-x0]^-1 with x in the flat frame.
    const glm::dvec2 du1 = uv[t.y] - uv[t.x], du2 = uv[t.z] - uv[t.x];
    const double inv00 = 1 / flat[1].x, inv01 = -flat[2].x / (flat[1].x * flat[2].y), inv11 = 1 / flat[2].y;
    const double j00 = du1.x * inv00, j01 = du1.x * inv01 + du2.x * inv11;
    const double j10 = du1.y * inv00, j11 = du1.y * inv01 + du2.y * inv11;
    // Singular values of a 2x2 matrix in closed form.
    const double e = 0.5 * (j00 + j11), f = 0.5 * (j00 - j11), g = 0.5 * (j10 + j01), h = 0.5 * (j10 - j01);
    const double qn = std::hypot(e, h), rn = std::hypot(f, g);
    const double s1 = qn + rn, s2 = std::abs(qn - rn);
    const double stretch = s2 > 0 ? s1 / s2 : std::numeric_limits<double>::infinity();
    const double ratio = std::abs(detail::signed_area(uv[t.x], uv[t.y], uv[t.z])) * normalise / a3;
    q.stretch_max = std::max(q.stretch_max, stretch);
    weighted_stretch += a3 * stretch;
    weighted_area += a3;
    q.area_ratio_min = std::min(q.area_ratio_min, ratio);
    q.area_ratio_max = std::max(q.area_ratio_max, ratio);
    q.area_distortion_mean += a3 * std::abs(ratio - 1);
  }
  if (weighted_area > 0) {
    q.stretch_mean = weighted_stretch / weighted_area;
    q.area_distortion_mean /= weighted_area;
  }
  return q;
}

}  // namespace paver
