#pragma once
// The per-item work of one solver iteration on the CPU. The arithmetic is solver_contract.h's,
// which the shaders include too; what is here is only the walk over the CPU's arrays, which
// shaders/solver_*.comp do over their buffers in the same order.
//   1. lift_particle  (per particle): locate in M^, pull strays back, lift P and kappa (eq. 2, 3)
//   2. update_spring  (per spring, in the contract): L_ab (eq. 4-6), l_ab, filter (eq. 15, 16)
//   3. move_particle  (per particle): R (eq. 7-9), L (eq. 10-11), G (eq. 12), update (eq. 13-14)
#include "solver/solver_contract.h"
#include "solver/solver_surface.h"
#include "solver/spring_system.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace paver {

namespace kernels {

// Triangle containing p, or -1. Within a cell the first triangle with all coordinates >= 0
// wins; else the best one within a small tolerance (points on shared edges).
inline int locate(const SolverSurface& s, glm::vec2 p, glm::vec3& bary) {
  const float rx = (p.x - s.grid_origin.x) / s.grid_cell_size;
  const float ry = (p.y - s.grid_origin.y) / s.grid_cell_size;
  if (!(rx >= 0.0f && ry >= 0.0f && rx < float(s.grid_nx) && ry < float(s.grid_ny))) return -1;
  const int cell = int(ry) * s.grid_nx + int(rx);
  int best = -1;
  float best_min = -1e-5f;
  for (int i = s.grid_start[cell]; i < s.grid_start[cell + 1]; ++i) {
    const int t = s.grid_triangles[i];
    const glm::vec3 b = barycentric(p, s.uv[s.triangles[3 * t]], s.uv[s.triangles[3 * t + 1]],
                                    s.uv[s.triangles[3 * t + 2]]);
    const float lowest = min_f(b.x, min_f(b.y, b.z));
    if (lowest >= 0.0f) {
      bary = b;
      return t;
    }
    if (lowest > best_min) {
      best_min = lowest;
      best = t;
      bary = b;
    }
  }
  if (best >= 0) bary = clamp_barycentric(bary);
  return best;
}

// The point of the boundary nearest to p, nudged into the map (the NOTES' reading of strays).
// `segment` receives the boundary segment it lies on: the nearest, the lower index on a tie. A map
// that wraps scans every segment; one that does not searches the binned segments ring by ring
// (solver_contract.h), which finds the same one.
inline glm::vec2 pull_back(const SolverSurface& s, glm::vec2 p, int& segment) {
  float best = INFINITY;
  glm::vec2 result = p;
  const auto consider = [&](int i) {
    const BoundaryCandidate candidate = wrapped_boundary_candidate(
        s.period, p, glm::vec2(s.boundary_segments[i].x, s.boundary_segments[i].y),
        glm::vec2(s.boundary_segments[i].z, s.boundary_segments[i].w), s.boundary_inward[i]);
    if (candidate.dist2 < best || (candidate.dist2 == best && i < segment)) {
      best = candidate.dist2;
      segment = i;
      result = candidate.nudged;
    }
  };
  if (s.period > 0.0f) {
    for (int i = 0; i < static_cast<int>(s.boundary_segments.size()); ++i) consider(i);
    return result;
  }
  const int nx = s.grid_nx, ny = s.grid_ny;
  const auto consider_cell = [&](int x, int y) {
    const int cell = y * nx + x;
    for (int k = s.boundary_grid_start[cell]; k < s.boundary_grid_start[cell + 1]; ++k) consider(s.boundary_grid_segments[k]);
  };
  const int cx = clamped_cell(p.x, s.grid_origin.x, s.grid_cell_size, nx);
  const int cy = clamped_cell(p.y, s.grid_origin.y, s.grid_cell_size, ny);
  for (int r = 0;; ++r) {
    const int x0 = cx - r, x1 = cx + r, y0 = cy - r, y1 = cy + r;
    for (int y = std::max(y0, 0); y <= std::min(y1, ny - 1); ++y) {
      if (y == y0 || y == y1) {
        for (int x = std::max(x0, 0); x <= std::min(x1, nx - 1); ++x) consider_cell(x, y);
      } else {
        if (x0 >= 0) consider_cell(x0, y);
        if (x1 < nx) consider_cell(x1, y);
      }
    }
    const float unsearched = unsearched_distance(p, s.grid_origin, s.grid_cell_size, nx, ny, x0, x1, y0, y1);
    if (pull_back_search_done(unsearched, best, s.grid_cell_size)) break;
  }
  return result;
}

struct LiftedParticle {
  glm::vec3 position;
  float curvature;
};

// Lifts particle p, wrapped into the period on a map that wraps; strays are first pulled back (p
// is updated in place). `hint` is the triangle
// the particle was in last time: particles move little per iteration, so it usually still
// contains p and the grid search is skipped. It is updated.
inline LiftedParticle lift_particle(const SolverSurface& s, glm::vec2& p, std::int32_t& hint) {
  p = wrap_position(s.period, s.period_origin, p);
  glm::vec3 b(0.0f);
  int t = -1;
  if (hint >= 0) {
    b = barycentric(p, s.uv[s.triangles[3 * hint]], s.uv[s.triangles[3 * hint + 1]], s.uv[s.triangles[3 * hint + 2]]);
    if (b.x >= 0.0f && b.y >= 0.0f && b.z >= 0.0f) t = hint;
  }
  if (t < 0) t = locate(s, p, b);
  if (t < 0) {
    int segment = 0;
    const glm::vec2 stray = p;
    p = pull_back(s, p, segment);
    t = locate(s, p, b);
    if (t < 0) {
      // Rounding left the nudged point outside: the triangle's centroid is inside for sure.
      p = nearest_image(s.period, s.boundary_inward[segment], stray);
      t = locate(s, p, b);
    }
    if (t < 0) return {glm::vec3(NAN), 0.0f};  // cannot happen for a valid map; caught by the caller
  }
  hint = t;
  const int i = s.triangles[3 * t], j = s.triangles[3 * t + 1], k = s.triangles[3 * t + 2];
  const glm::vec4 lifted = lift_barycentric(b, s.position[i], s.position[j], s.position[k], s.curvature[i],
                                             s.curvature[j], s.curvature[k]);
  LiftedParticle out;
  out.position = glm::vec3(lifted);
  out.curvature = lifted.w;
  return out;
}

struct Move {
  glm::vec2 position;  // p^{t+1}
  float step;          // |dp * dt|
};

// One particle: gathers R, L, G over its springs (eq. 7-13) and moves (eq. 14).
inline Move move_particle(const SolverConstants& k, const SpringSystem& sys, int a,
                          const std::vector<glm::vec2>& position) {
  const glm::vec2 pa = position[a];
  if (!particle_moves(sys.stray_count[a])) return {pa, 0.0f};
  SpringSums sums = no_spring_sums();
  for (int i = sys.neighbor_start[a]; i < sys.neighbor_start[a + 1]; ++i) {
    const int nb = sys.neighbor[i];
    if (sys.stray_count[nb] == kRetired) continue;
    const glm::vec2 pb = nearest_image(k.period, position[nb], pa);
    const int spring = sys.neighbor_spring[i];
    const float l = sys.target[spring];
    const glm::vec2 d = pb - pa;
    const float len = length_2d(d);
    if (spring_is_slack(sys.spring_flags[spring], len, l)) continue;
    sums = accumulate_spring(k, sums, pb, d, len, l, nb > a ? 1.0f : -1.0f);
  }
  if (sums.used == 0) return {pa, 0.0f};
  const glm::vec2 step = particle_step(k, pa, sums);
  return {glm::vec2(pa.x + step.x, pa.y + step.y), length_2d(step)};
}

}  // namespace kernels
}  // namespace paver
