#pragma once
// The per-item work of one solver iteration, in float32 with a fixed operation order, so that
// shaders/*.comp can reproduce it bit for bit (they mirror these functions line by line; the
// project builds with -ffp-contract=off, the shaders mark temporaries `precise`).
//   1. lift_particle  (per particle): locate in M^, pull strays back, lift P and kappa (eq. 2, 3)
//   2. update_spring  (per spring):   L_ab (eq. 4-6), l_ab, adaptive filter (eq. 15, 16)
//   3. move_particle  (per particle): R (eq. 7-9), L (eq. 10-11), G (eq. 12), update (eq. 13-14)
#include "solver/solver_surface.h"
#include "solver/spring_system.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <cstdint>

namespace paver {

// Solver parameters as the kernels use them (a push-constant block on the GPU).
struct SolverConstants {
  float c, m;                       // eq. 5
  float alpha, beta, gamma;         // eq. 8
  float lambda_r, lambda_l, lambda_g;  // eq. 13
  float dt;                         // eq. 14
  float mu_compressed, mu_stretched, filter_max;  // eq. 16 and the clamp
  float curvature_min, curvature_inv_range;       // eq. 5 normalisation
  glm::vec2 centre;                 // O(M^), eq. 12
  std::uint32_t filter_base_initial;  // 1: clamp against l_ab at initialisation, 0: current l_ab
  std::uint32_t stray_patience;       // pulls back in a row before a particle retires; 0 = never
};

namespace kernels {

// min / max as GLSL defines them for non-NaN input, inlined (std::fmin is a library call).
inline float min_f(float a, float b) { return b < a ? b : a; }
inline float max_f(float a, float b) { return a < b ? b : a; }

// Barycentric coordinates of p in triangle (a, b, c); same expression as uv_grid.cpp in double.
inline glm::vec3 barycentric(glm::vec2 p, glm::vec2 a, glm::vec2 b, glm::vec2 c) {
  const glm::vec2 v0 = b - a, v1 = c - a, v2 = p - a;
  const float det = v0.x * v1.y - v0.y * v1.x;
  const float w1 = (v2.x * v1.y - v2.y * v1.x) / det;
  const float w2 = (v0.x * v2.y - v0.y * v2.x) / det;
  return {1.0f - w1 - w2, w1, w2};
}

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
  if (best >= 0) {
    bary = glm::vec3(max_f(bary.x, 0.0f), max_f(bary.y, 0.0f), max_f(bary.z, 0.0f));
    const float sum = bary.x + bary.y + bary.z;
    bary = glm::vec3(bary.x / sum, bary.y / sum, bary.z / sum);
  }
  return best;
}

// The point of the boundary nearest to p, nudged into the map (the NOTES' reading of strays).
// `segment` receives the boundary segment it lies on.
inline glm::vec2 pull_back(const SolverSurface& s, glm::vec2 p, int& segment) {
  const int n = static_cast<int>(s.boundary_uv.size());
  float best = INFINITY;
  glm::vec2 result = p;
  for (int i = 0; i < n; ++i) {
    const glm::vec2 a = s.boundary_uv[i], b = s.boundary_uv[i + 1 == n ? 0 : i + 1];
    const glm::vec2 ab = b - a, ap = p - a;
    const float len2 = ab.x * ab.x + ab.y * ab.y;
    float t = len2 > 0.0f ? (ap.x * ab.x + ap.y * ab.y) / len2 : 0.0f;
    t = min_f(max_f(t, 0.0f), 1.0f);
    const glm::vec2 q(a.x + t * ab.x, a.y + t * ab.y);
    const glm::vec2 d = p - q;
    const float dist2 = d.x * d.x + d.y * d.y;
    if (dist2 < best) {
      best = dist2;
      segment = i;
      const glm::vec2 in = s.boundary_inward[i];
      result = glm::vec2(q.x + 0.01f * (in.x - q.x), q.y + 0.01f * (in.y - q.y));
    }
  }
  return result;
}

struct LiftedParticle {
  glm::vec3 position;
  float curvature;
};

// Lifts particle p; strays are first pulled back (p is updated in place). `hint` is the triangle
// the particle was in last time: particles move little per iteration, so it usually still
// contains p and the grid search is skipped. It is updated.
inline LiftedParticle lift_particle(const SolverSurface& s, glm::vec2& p, std::int32_t& hint) {
  glm::vec3 b(0.0f);
  int t = -1;
  if (hint >= 0) {
    b = barycentric(p, s.uv[s.triangles[3 * hint]], s.uv[s.triangles[3 * hint + 1]], s.uv[s.triangles[3 * hint + 2]]);
    if (b.x >= 0.0f && b.y >= 0.0f && b.z >= 0.0f) t = hint;
  }
  if (t < 0) t = locate(s, p, b);
  if (t < 0) {
    int segment = 0;
    p = pull_back(s, p, segment);
    t = locate(s, p, b);
    if (t < 0) {
      // Rounding left the nudged point outside: the triangle's centroid is inside for sure.
      p = s.boundary_inward[segment];
      t = locate(s, p, b);
    }
    if (t < 0) return {glm::vec3(NAN), 0.0f};  // cannot happen for a valid map; caught by the caller
  }
  hint = t;
  const int i = s.triangles[3 * t], j = s.triangles[3 * t + 1], k = s.triangles[3 * t + 2];
  const glm::vec4 pi = s.position[i], pj = s.position[j], pk = s.position[k];
  LiftedParticle out;
  out.position = glm::vec3(b.x * pi.x + b.y * pj.x + b.z * pk.x, b.x * pi.y + b.y * pj.y + b.z * pk.y,
                           b.x * pi.z + b.y * pj.z + b.z * pk.z);
  out.curvature = b.x * s.curvature[i] + b.y * s.curvature[j] + b.z * s.curvature[k];
  return out;
}

// New stray count of a particle after a lift that did (or did not) pull it back: +2 for a pull
// back, -1 otherwise, so a particle pushed out every iteration retires after `stray_patience`
// iterations and one that goes out every other iteration after about twice that, while an
// occasional stray recovers.
inline std::uint32_t next_stray_count(const SolverConstants& k, std::uint32_t count, bool pulled_back) {
  if (count == kRetired) return kRetired;
  if (!pulled_back) return count > 0u ? count - 1u : 0u;
  const std::uint32_t next = count + 2u;
  return k.stray_patience != 0u && next >= 2u * k.stray_patience ? kRetired : next;
}

// 3D target length L_ab (eq. 4-6).
inline float target_length_3d(const SolverConstants& k, float rest, float kappa_a, float kappa_b) {
  float normalised = (max_f(kappa_a, kappa_b) - k.curvature_min) * k.curvature_inv_range;
  normalised = min_f(max_f(normalised, 0.0f), 1.0f);
  return (k.c + k.m * normalised) * rest + rest;
}

struct SpringState {
  float target;     // filtered 2D target l^{t+1}
  float ratio_3d;   // |P_a P_b| / L_ab: how far the spring is from its 3D target
};

// One spring: the 2D target from the local distortion and the adaptive filter (eq. 15, 16).
// `reset` restarts the filter from the unfiltered target: at initialisation, and when an end was
// just pulled back onto the map (its wound-up target would push it straight out again).
inline SpringState update_spring(const SolverConstants& k, glm::vec2 pa, glm::vec2 pb, glm::vec3 Pa,
                                 glm::vec3 Pb, float kappa_a, float kappa_b, float rest,
                                 float previous, float initial, bool reset, std::uint32_t flags) {
  const glm::vec2 d2 = pb - pa;
  const glm::vec3 d3 = Pb - Pa;
  const float len2 = std::sqrt(d2.x * d2.x + d2.y * d2.y);
  const float len3 = std::sqrt(d3.x * d3.x + d3.y * d3.y + d3.z * d3.z);
  const float target3 = (flags & kSpringContact) != 0u ? rest : target_length_3d(k, rest, kappa_a, kappa_b);
  // l_ab = L_ab |p_a p_b| / |P_a P_b|; a collapsed spring keeps the plain 3D target.
  const float raw = len3 > 0.0f && len2 > 0.0f ? target3 * len2 / len3 : target3;
  // Virtual springs only keep the structure: the filter's extra push would make them fight the
  // pattern's own springs (a chord across a curved face is shorter than the face), so they keep
  // the unfiltered target; so do contact springs, whose target is exact.
  if (reset || flags != 0u) return {raw, len3 / target3};
  const float mu = len3 < target3 ? k.mu_compressed : k.mu_stretched;
  const float w = 1.0f + mu * (1.0f - len3 / target3);
  const float base = k.filter_base_initial != 0u ? initial : raw;
  const float filtered = min_f(max_f(w * previous, base), k.filter_max * base);
  return {filtered, len3 / target3};
}

// k_c(r) = alpha / r^12 - beta / r^6 + gamma (eq. 8).
inline float spring_constant(const SolverConstants& k, float r) {
  const float r2 = r * r;
  const float r6 = r2 * r2 * r2;
  const float r12 = r6 * r6;
  return k.alpha / r12 - k.beta / r6 + k.gamma;
}

struct Move {
  glm::vec2 position;  // p^{t+1}
  float step;          // |dp * dt|
};

// One particle: gathers R, L, G over its springs (eq. 7-13) and moves (eq. 14).
inline Move move_particle(const SolverConstants& k, const SpringSystem& sys, int a,
                          const std::vector<glm::vec2>& position) {
  const glm::vec2 pa = position[a];
  if (sys.stray_count[a] == kRetired) return {pa, 0.0f};
  glm::vec2 force(0.0f), centroid(0.0f);
  float k_sum = 0.0f, w_sum = 0.0f, stretch_sum = 0.0f;
  const int begin = sys.neighbor_start[a], end = sys.neighbor_start[a + 1];
  int used = 0;
  for (int i = begin; i < end; ++i) {
    if (sys.stray_count[sys.neighbor[i]] == kRetired) continue;
    const glm::vec2 pb = position[sys.neighbor[i]];
    const int spring = sys.neighbor_spring[i];
    const float l = sys.target[spring];
    const glm::vec2 d = pb - pa;
    const float len = std::sqrt(d.x * d.x + d.y * d.y);
    if ((sys.spring_flags[spring] & kSpringContact) != 0u && len >= l) continue;  // contacts only push
    // k_c is clamped at r = 0.1: below it alpha / r^12 overflows (inf - inf = NaN at r = 0).
    const float kc = spring_constant(k, max_f(len / l, 0.1f));
    // F_ab = k_c (|p_a p_b| - l_ab) unit(p_b - p_a). Coincident ends have no direction: they
    // separate along x, the lower index to the left, so the two sides push apart.
    const glm::vec2 unit = len > 1e-6f * l ? glm::vec2(d.x / len, d.y / len)
                                           : glm::vec2(sys.neighbor[i] > a ? 1.0f : -1.0f, 0.0f);
    const float f = kc * (len - l);
    force = glm::vec2(force.x + f * unit.x, force.y + f * unit.y);
    ++used;
    k_sum = k_sum + kc;
    centroid = glm::vec2(centroid.x + pb.x / l, centroid.y + pb.y / l);  // eq. 11 with p_b
    w_sum = w_sum + 1.0f / l;
    stretch_sum = stretch_sum + (len - l);
  }
  if (used == 0) return {pa, 0.0f};
  const glm::vec2 restoring(force.x / k_sum, force.y / k_sum);              // eq. 9
  const glm::vec2 local(centroid.x / w_sum - pa.x, centroid.y / w_sum - pa.y);  // eq. 10
  const glm::vec2 to_centre = k.centre - pa;
  const float centre_dist = std::sqrt(to_centre.x * to_centre.x + to_centre.y * to_centre.y);
  const float g = centre_dist > 0.0f ? stretch_sum / float(used) / centre_dist : 0.0f;
  const glm::vec2 global(g * to_centre.x, g * to_centre.y);                 // eq. 12
  const glm::vec2 dp(k.lambda_r * restoring.x + k.lambda_l * local.x + k.lambda_g * global.x,
                     k.lambda_r * restoring.y + k.lambda_l * local.y + k.lambda_g * global.y);
  const glm::vec2 step(dp.x * k.dt, dp.y * k.dt);
  return {glm::vec2(pa.x + step.x, pa.y + step.y), std::sqrt(step.x * step.x + step.y * step.y)};
}

}  // namespace kernels
}  // namespace paver
