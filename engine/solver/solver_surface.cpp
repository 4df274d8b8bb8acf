#include "solver/solver_surface.h"

#include <glm/common.hpp>

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
  const float values[] = {s.grid_origin.x, s.grid_origin.y, s.grid_cell_size, s.curvature_min, s.curvature_max,
                          s.centre.x, s.centre.y};
  const std::int32_t sizes[] = {s.grid_nx, s.grid_ny};
  h.add(values, sizeof values);
  h.add(sizes, sizeof sizes);
  return h.value();
}

}  // namespace

SolverSurface make_solver_surface(const SurfaceMap& map) {
  SolverSurface s;
  const auto& mesh = map.mesh;
  s.uv.reserve(map.uv.size());
  for (const auto& q : map.uv) s.uv.emplace_back(float(q.x), float(q.y));
  // The solver uses 3D differences only: centred before the cast to float32, a part far from the
  // origin keeps the precision of one at it.
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (const auto& p : mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const glm::dvec3 middle = mesh.positions.empty() ? glm::dvec3(0) : 0.5 * (lo + hi);
  s.position.reserve(mesh.positions.size());
  for (const auto& p : mesh.positions) {
    const glm::dvec3 q = p - middle;
    s.position.emplace_back(float(q.x), float(q.y), float(q.z), 0.0f);
  }
  s.curvature.assign(map.curvature.begin(), map.curvature.end());
  s.triangles.reserve(mesh.triangles.size() * 3);
  for (const auto& t : mesh.triangles) s.triangles.insert(s.triangles.end(), {t.x, t.y, t.z});
  s.grid_origin = glm::vec2(map.grid.origin);
  s.grid_cell_size = float(map.grid.cell_size);
  s.grid_nx = map.grid.nx;
  s.grid_ny = map.grid.ny;
  s.grid_start = map.grid.cell_start;
  s.grid_triangles = map.grid.cell_triangles;

  // Boundary segments and the triangle each belongs to (the one using it as an edge).
  const std::vector<glm::ivec2> segments = boundary_segments(mesh);
  const int n = static_cast<int>(segments.size());
  s.boundary_segments.resize(n);
  s.boundary_inward.resize(n);
  // Each boundary vertex starts exactly one segment (the loops are disjoint).
  std::vector<int> next(mesh.vertex_count(), -1), segment_of(mesh.vertex_count(), -1);
  for (int i = 0; i < n; ++i) {
    next[segments[i].x] = segments[i].y;
    segment_of[segments[i].x] = i;
    s.boundary_segments[i] = glm::vec4(glm::vec2(map.uv[segments[i].x]), glm::vec2(map.uv[segments[i].y]));
  }
  for (const auto& t : mesh.triangles) {
    const int c[3] = {t.x, t.y, t.z};
    for (int k = 0; k < 3; ++k) {
      const int a = c[k], b = c[(k + 1) % 3];
      if (next[a] == b) {
        const glm::dvec2 centroid = (map.uv[t.x] + map.uv[t.y] + map.uv[t.z]) / 3.0;
        s.boundary_inward[segment_of[a]] = glm::vec2(centroid);
      }
    }
  }
  s.curvature_min = float(map.curvature_min);
  s.curvature_max = float(map.curvature_max);
  s.centre = glm::vec2(0.5 * (map.uv_min + map.uv_max));
  s.fingerprint = fingerprint_of(s);
  return s;
}

}  // namespace paver
