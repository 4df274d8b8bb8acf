#include "map/uv_grid.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace paver {

UvGrid build_uv_grid(const std::vector<glm::dvec2>& uv, const std::vector<glm::ivec3>& triangles,
                     double triangles_per_cell) {
  UvGrid g;
  glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (const auto& p : uv) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const glm::dvec2 extent = glm::max(hi - lo, glm::dvec2(1e-12));
  const double cells = std::max(1.0, double(triangles.size()) / triangles_per_cell);
  g.cell_size = std::sqrt(extent.x * extent.y / cells);
  g.nx = std::max(1, int(std::ceil(extent.x / g.cell_size)));
  g.ny = std::max(1, int(std::ceil(extent.y / g.cell_size)));
  // Pad by a hair so points on the far boundary fall inside the last cell.
  g.origin = lo - glm::dvec2(1e-9 * g.cell_size);
  g.cell_size *= 1 + 1e-9;

  auto cell_range = [&](const glm::ivec3& t, glm::ivec2& c0, glm::ivec2& c1) {
    const glm::dvec2 a = glm::min(glm::min(uv[t.x], uv[t.y]), uv[t.z]);
    const glm::dvec2 b = glm::max(glm::max(uv[t.x], uv[t.y]), uv[t.z]);
    c0 = glm::clamp(glm::ivec2(glm::floor((a - g.origin) / g.cell_size)), glm::ivec2(0), glm::ivec2(g.nx - 1, g.ny - 1));
    c1 = glm::clamp(glm::ivec2(glm::floor((b - g.origin) / g.cell_size)), glm::ivec2(0), glm::ivec2(g.nx - 1, g.ny - 1));
  };
  g.cell_start.assign(size_t(g.nx) * g.ny + 1, 0);
  glm::ivec2 c0, c1;
  for (const auto& t : triangles) {
    cell_range(t, c0, c1);
    for (int y = c0.y; y <= c1.y; ++y)
      for (int x = c0.x; x <= c1.x; ++x) ++g.cell_start[size_t(y) * g.nx + x + 1];
  }
  for (size_t c = 1; c < g.cell_start.size(); ++c) g.cell_start[c] += g.cell_start[c - 1];
  g.cell_triangles.resize(g.cell_start.back());
  std::vector<std::int32_t> fill(g.cell_start.begin(), g.cell_start.end() - 1);
  for (size_t i = 0; i < triangles.size(); ++i) {
    cell_range(triangles[i], c0, c1);
    for (int y = c0.y; y <= c1.y; ++y)
      for (int x = c0.x; x <= c1.x; ++x) g.cell_triangles[fill[size_t(y) * g.nx + x]++] = std::int32_t(i);
  }
  return g;
}

glm::dvec3 barycentric(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
  const glm::dvec2 v0 = b - a, v1 = c - a, v2 = p - a;
  const double det = v0.x * v1.y - v0.y * v1.x;
  const double w1 = (v2.x * v1.y - v2.y * v1.x) / det;
  const double w2 = (v0.x * v2.y - v0.y * v2.x) / det;
  return {1 - w1 - w2, w1, w2};
}

int locate(const UvGrid& grid, const std::vector<glm::dvec2>& uv,
           const std::vector<glm::ivec3>& triangles, glm::dvec2 p, glm::dvec3& bary) {
  const glm::dvec2 rel = (p - grid.origin) / grid.cell_size;
  if (!(rel.x >= 0 && rel.y >= 0 && rel.x < grid.nx && rel.y < grid.ny)) return -1;
  const size_t cell = size_t(int(rel.y)) * grid.nx + size_t(int(rel.x));
  // Points on a shared edge may be rejected by both triangles by rounding; accept the best
  // candidate within a small tolerance instead.
  constexpr double tolerance = 1e-10;
  int best = -1;
  double best_min = -tolerance;
  for (int i = grid.cell_start[cell]; i < grid.cell_start[cell + 1]; ++i) {
    const int t = grid.cell_triangles[i];
    const glm::ivec3 tri = triangles[t];
    const glm::dvec3 b = barycentric(p, uv[tri.x], uv[tri.y], uv[tri.z]);
    const double lowest = std::min(b.x, std::min(b.y, b.z));
    if (lowest >= 0) {
      bary = b;
      return t;
    }
    if (lowest >= best_min) best_min = lowest, best = t, bary = b;
  }
  if (best >= 0) {
    bary = glm::max(bary, glm::dvec3(0));
    bary /= bary.x + bary.y + bary.z;
  }
  return best;
}

}  // namespace paver
