#version 450
// Pass 2 of an iteration, per spring: L_ab (eq. 4-6), the 2D target from the local distortion
// and the adaptive filter (eq. 15, 16), as CpuSpringSolver::update_springs.
// Push constants: pc.first = 1 runs the pass even when the solve is done (the initial pass).
#extension GL_GOOGLE_include_directive : require
#include "solver_common.glsl"

void main() {
  int s = int(gl_GlobalInvocationID.x);
  if (s >= P.spring_count) return;
  if (pc.first == 0u && solver_done()) return;
  int a = spring_a[s], b = spring_b[s];
  float previous = target[s];
  bool fresh = previous <= 0.0f;
  bool reset = fresh || pulled_back[a] != 0u || pulled_back[b] != 0u;
  precise vec2 d2 = nearest_image(P.period, position_in[b], position_in[a]) - position_in[a];
  precise vec3 d3 = lifted[b].xyz - lifted[a].xyz;
  SpringState state = update_spring(P, d2, d3, lifted[a].w, lifted[b].w, rest_length[s], previous,
                                    initial_target[s], reset, spring_flags[s]);
  target[s] = state.target;
  if (fresh) initial_target[s] = state.target;
}
