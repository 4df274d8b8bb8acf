#include "solver/solver_surface.h"

#include "solver/solver_contract.h"

#include <glm/common.hpp>

#include <algorithm>
#include <array>
#include <limits>

namespace paver {
namespace {

// FNV-1a, 64 bits, over raw bytes.
class Fnv1a {
public:
  void add(const void* data, std::size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i) hash_ = (hash_ ^ p[i]) * 1099511628211ull;
  }
  template <class T>
  void add(const std::vector<T>& v) { add(v.data(), v.size() * sizeof(T)); }
  std::uint64_t value() const { return hash_; }

private:
  std::uint64_t hash_ = 1469598103934665603ull;
};

std::uint64_t fingerprint_of(const SolverSurface& s) {
  Fnv1a h;
  h.add(s.uv), h.add(s.position), h.add(s.curvature), h.add(s.triangles);
  h.add(s.grid_start), h.add(s.grid_triangles), h.add(s.boundary_segments), h.add(s.boundary_inward);
  h.add(s.boundary_grid_start), h.add(s.boundary_grid_segments);
  const float values[] = {s.grid_origin.x, s.grid_origin.y, s.grid_cell_size, s.curvature_min, s.curvature_max,
                          s.centre.x, s.centre.y, s.period, s.period_origin};
  const std::int32_t sizes[] = {s.grid_nx, s.grid_ny};
  h.add(values, sizeof values);
  h.add(sizes, sizeof sizes);
  return h.value();
}

// Bins each boundary segment in the grid cells its bounding box overlaps, one cell more on each
// side so that float32 rounding of a cell index never hides a segment from its own cell.
void bin_boundary_segments(SolverSurface& s) {
  const int cells = s.grid_nx * s.grid_ny;
  const auto cell_range = [&](int i, int& x0, int& x1, int& y0, int& y1) {
    const glm::vec4 e = s.boundary_segments[std::size_t(i)];
    x0 = std::max(0, clamped_cell(std::min(e.x, e.z), s.grid_origin.x, s.grid_cell_size, s.grid_nx) - 1);
    x1 = std::min(s.grid_nx - 1, clamped_cell(std::max(e.x, e.z), s.grid_origin.x, s.grid_cell_size, s.grid_nx) + 1);
    y0 = std::max(0, clamped_cell(std::min(e.y, e.w), s.grid_origin.y, s.grid_cell_size, s.grid_ny) - 1);
    y1 = std::min(s.grid_ny - 1, clamped_cell(std::max(e.y, e.w), s.grid_origin.y, s.grid_cell_size, s.grid_ny) + 1);
  };
  s.boundary_grid_start.assign(std::size_t(cells) + 1, 0);
  const int n = int(s.boundary_segments.size());
  int x0, x1, y0, y1;
  for (int i = 0; i < n; ++i) {
    cell_range(i, x0, x1, y0, y1);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) ++s.boundary_grid_start[std::size_t(y * s.grid_nx + x) + 1];
  }
  for (int c = 0; c < cells; ++c) s.boundary_grid_start[std::size_t(c) + 1] += s.boundary_grid_start[std::size_t(c)];
  s.boundary_grid_segments.resize(std::size_t(s.boundary_grid_start.back()));
  std::vector<std::int32_t> fill(s.boundary_grid_start.begin(), s.boundary_grid_start.end() - 1);
  for (int i = 0; i < n; ++i) {
    cell_range(i, x0, x1, y0, y1);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) s.boundary_grid_segments[std::size_t(fill[std::size_t(y * s.grid_nx + x)]++)] = i;
  }
}

}  // namespace

SolverSurface make_solver_surface(const SurfaceMap& map) {
  SolverSurface s;
  const auto& mesh = map.mesh;
  const bool wraps = map_wraps(map);
  // The vertex behind each solver vertex: the mesh's own, or the domain's copies of them.
  const std::vector<glm::dvec2>& uv = wraps ? map.domain.uv : map.uv;
  const auto vertex_of = [&](std::size_t d) { return wraps ? std::size_t(map.domain.vertex[d]) : d; };
  s.uv.reserve(uv.size());
  for (const auto& q : uv) s.uv.emplace_back(float(q.x), float(q.y));
  // The solver uses 3D differences only: centred before the cast to float32, a part far from the
  // origin keeps the precision of one at it.
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (const auto& p : mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const glm::dvec3 middle = mesh.positions.empty() ? glm::dvec3(0) : 0.5 * (lo + hi);
  s.position.reserve(uv.size());
  s.curvature.reserve(uv.size());
  for (std::size_t d = 0; d < uv.size(); ++d) {
    const glm::dvec3 q = mesh.positions[vertex_of(d)] - middle;
    s.position.emplace_back(float(q.x), float(q.y), float(q.z), 0.0f);
    s.curvature.push_back(float(map.curvature[vertex_of(d)]));
  }
  const std::vector<glm::ivec3>& triangles = wraps ? map.domain.triangles : mesh.triangles;
  s.triangles.reserve(triangles.size() * 3);
  for (const auto& t : triangles) s.triangles.insert(s.triangles.end(), {t.x, t.y, t.z});
  s.grid_origin = glm::vec2(map.grid.origin);
  s.grid_cell_size = float(map.grid.cell_size);
  s.grid_nx = map.grid.nx;
  s.grid_ny = map.grid.ny;
  s.grid_start = map.grid.cell_start;
  s.grid_triangles = map.grid.cell_triangles;
  s.period = float(map.period);
  s.period_origin = float(map.period_origin);

  // Boundary segments, each with the triangle that has it as an edge, in one piece with it.
  const std::vector<glm::ivec2> segments = boundary_segments(mesh);
  const int n = static_cast<int>(segments.size());
  s.boundary_segments.resize(n);
  s.boundary_inward.resize(n);
  // Each boundary vertex starts exactly one segment (the loops are disjoint).
  std::vector<int> next(mesh.vertex_count(), -1), segment_of(mesh.vertex_count(), -1);
  for (int i = 0; i < n; ++i) {
    next[segments[i].x] = segments[i].y;
    segment_of[segments[i].x] = i;
  }
  for (int f = 0; f < mesh.face_count(); ++f) {
    const glm::ivec3 t = mesh.triangles[f];
    const std::array<glm::dvec2, 3> corner = triangle_uv(map, f);
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      if (next[a] == b) {
        const glm::dvec2 centroid = (corner[0] + corner[1] + corner[2]) / 3.0;
        s.boundary_segments[segment_of[a]] = glm::vec4(glm::vec2(corner[k]), glm::vec2(corner[(k + 1) % 3]));
        s.boundary_inward[segment_of[a]] = glm::vec2(centroid);
      }
    }
  }
  bin_boundary_segments(s);
  s.curvature_min = float(map.curvature_min);
  s.curvature_max = float(map.curvature_max);
  s.centre = glm::vec2(0.5 * (map.uv_min + map.uv_max));
  s.fingerprint = fingerprint_of(s);
  return s;
}

}  // namespace paver
