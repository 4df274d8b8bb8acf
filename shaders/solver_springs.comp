#version 450
// Pass 2 of an iteration, per spring: L_ab (eq. 4-6), the 2D target from the local distortion
// and the adaptive filter (eq. 15, 16). Mirrors kernels::update_spring and
// CpuSpringSolver::update_springs.
#extension GL_GOOGLE_include_directive : require
#include "solver_common.glsl"

layout(push_constant) uniform Push {
  uint always;  // 1: run even when the solve is done (the initial pass)
} pc;

float target_length_3d(float rest, float kappa_a, float kappa_b) {
  precise float normalised = (max_f(kappa_a, kappa_b) - P.curvature_min) * P.curvature_inv_range;
  normalised = min_f(max_f(normalised, 0.0), 1.0);
  precise float result = (P.c + P.m * normalised) * rest + rest;
  return result;
}

void main() {
  int s = int(gl_GlobalInvocationID.x);
  if (s >= P.spring_count) return;
  if (pc.always == 0u && solver_done()) return;
  int a = spring_a[s], b = spring_b[s];
  uint flags = spring_flags[s];
  float previous = target[s];
  bool fresh = previous <= 0.0;
  bool reset = fresh || pulled_back[a] != 0u || pulled_back[b] != 0u;

  precise vec2 d2 = position_in[b] - position_in[a];
  precise vec3 d3 = lifted[b].xyz - lifted[a].xyz;
  precise float len2 = sqrt(d2.x * d2.x + d2.y * d2.y);
  precise float len3 = sqrt(d3.x * d3.x + d3.y * d3.y + d3.z * d3.z);
  float rest = rest_length[s];
  float target3 = (flags & kSpringContact) != 0u ? rest : target_length_3d(rest, lifted[a].w, lifted[b].w);
  precise float raw = len3 > 0.0 && len2 > 0.0 ? target3 * len2 / len3 : target3;
  float result;
  if (reset || flags != 0u) {
    result = raw;
  } else {
    float mu = len3 < target3 ? P.mu_compressed : P.mu_stretched;
    precise float w = 1.0 + mu * (1.0 - len3 / target3);
    float base = P.filter_base_initial != 0u ? initial_target[s] : raw;
    precise float grown = w * previous;
    precise float upper = P.filter_max * base;
    result = min_f(max_f(grown, base), upper);
  }
  target[s] = result;
  if (fresh) initial_target[s] = result;
}
