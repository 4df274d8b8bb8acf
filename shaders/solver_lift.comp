#version 450
// Pass 1 of an iteration, per particle: locate in M^, pull strays back, lift P and kappa
// (eq. 2, 3), as kernels::lift_particle and CpuSpringSolver::lift_all.
// Push constants: pc.first = 1 counts strays (0 for the closing lift after the last iteration);
// pc.second = 1 runs the pass even when the solve is done (the initial and closing lifts).
#extension GL_GOOGLE_include_directive : require
#include "solver_common.glsl"

vec3 corner_barycentric(int t, vec2 p) {
  return barycentric(p, uv[triangles[3 * t]], uv[triangles[3 * t + 1]], uv[triangles[3 * t + 2]]);
}

// As kernels::locate: the first triangle of p's grid cell with all coordinates >= 0, else the
// best one within a small tolerance (points on shared edges).
int locate(vec2 p, out vec3 bary) {
  bary = vec3(0.0f);
  precise float rx = (p.x - P.grid_origin.x) / P.grid_cell_size;
  precise float ry = (p.y - P.grid_origin.y) / P.grid_cell_size;
  if (!(rx >= 0.0f && ry >= 0.0f && rx < float(P.grid_nx) && ry < float(P.grid_ny))) return -1;
  int cell = int(ry) * P.grid_nx + int(rx);
  int best = -1;
  float best_min = -1e-5f;
  for (int i = grid_start[cell]; i < grid_start[cell + 1]; ++i) {
    int t = grid_triangles[i];
    vec3 b = corner_barycentric(t, p);
    float lowest = min_f(b.x, min_f(b.y, b.z));
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

// As kernels::pull_back: the nearest boundary point, nudged into the map; the nearest segment,
// the lower index on a tie. A map that wraps scans every segment; one that does not searches the
// binned segments ring by ring.
struct PullBack {
  float best;
  int segment;
  vec2 result;
};

void consider(inout PullBack s, vec2 p, int i) {
  BoundaryCandidate candidate = wrapped_boundary_candidate(P.period, p, boundary_segments[i].xy,
                                                           boundary_segments[i].zw, boundary_inward[i]);
  if (candidate.dist2 < s.best || (candidate.dist2 == s.best && i < s.segment)) {
    s.best = candidate.dist2;
    s.segment = i;
    s.result = candidate.nudged;
  }
}

void consider_cell(inout PullBack s, vec2 p, int x, int y) {
  int cell = y * P.grid_nx + x;
  for (int k = boundary_grid_start[cell]; k < boundary_grid_start[cell + 1]; ++k) consider(s, p, boundary_grid_segments[k]);
}

vec2 pull_back(vec2 p, out int segment) {
  PullBack s;
  s.best = uintBitsToFloat(0x7f800000u);  // +inf
  s.segment = 0;
  s.result = p;
  if (P.period > 0.0f) {
    for (int i = 0; i < P.boundary_count; ++i) consider(s, p, i);
  } else {
    int nx = P.grid_nx, ny = P.grid_ny;
    int cx = clamped_cell(p.x, P.grid_origin.x, P.grid_cell_size, nx);
    int cy = clamped_cell(p.y, P.grid_origin.y, P.grid_cell_size, ny);
    for (int r = 0;; ++r) {
      int x0 = cx - r, x1 = cx + r, y0 = cy - r, y1 = cy + r;
      for (int y = max(y0, 0); y <= min(y1, ny - 1); ++y) {
        if (y == y0 || y == y1) {
          for (int x = max(x0, 0); x <= min(x1, nx - 1); ++x) consider_cell(s, p, x, y);
        } else {
          if (x0 >= 0) consider_cell(s, p, x0, y);
          if (x1 < nx) consider_cell(s, p, x1, y);
        }
      }
      float unsearched = unsearched_distance(p, P.grid_origin, P.grid_cell_size, nx, ny, x0, x1, y0, y1);
      if (pull_back_search_done(unsearched, s.best, P.grid_cell_size)) break;
    }
  }
  segment = s.segment;
  return s.result;
}

void main() {
  int a = int(gl_GlobalInvocationID.x);
  if (a >= P.particle_count) return;
  if (pc.second == 0u && solver_done()) return;
  vec2 before = position_in[a];
  if (isnan(before.x) || isnan(before.y) || isinf(before.x) || isinf(before.y)) {
    atomicOr(control[kControlError], kErrorNonFinite);
    return;
  }
  // Wrapping into the period (a map that wraps) is not a pull back.
  vec2 wrapped = wrap_position(P.period, P.period_origin, before);
  vec2 p = wrapped;
  vec3 b = vec3(0.0f);
  int t = -1;
  int hint = triangle_hint[a];
  if (hint >= 0) {
    b = corner_barycentric(hint, p);
    if (b.x >= 0.0f && b.y >= 0.0f && b.z >= 0.0f) t = hint;
  }
  if (t < 0) t = locate(p, b);
  if (t < 0) {
    int segment;
    vec2 stray = p;
    p = pull_back(p, segment);
    t = locate(p, b);
    if (t < 0) {
      // Rounding left the nudged point outside: the triangle's centroid is inside for sure.
      p = nearest_image(P.period, boundary_inward[segment], stray);
      t = locate(p, b);
    }
    if (t < 0) {
      atomicOr(control[kControlError], kErrorNotLifted);
      return;
    }
  }
  triangle_hint[a] = t;
  position_in[a] = p;
  int i = triangles[3 * t], j = triangles[3 * t + 1], k = triangles[3 * t + 2];
  lifted[a] = lift_barycentric(b, surface_position[i], surface_position[j], surface_position[k],
                               surface_curvature[i], surface_curvature[j], surface_curvature[k]);
  if (pc.first == 0u) return;
  bool pulled = p != wrapped;
  pulled_back[a] = pulled ? 1u : 0u;
  stray_count[a] = next_stray_count(P, stray_count[a], pulled);
  if (pulled) atomicAdd(control[kControlStrays], 1u);
}
