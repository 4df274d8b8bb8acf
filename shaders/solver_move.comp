#version 450
// Pass 3 of an iteration, per particle: gather R (eq. 7-9), L (eq. 10-11 with p_b), G (eq. 12)
// over the CSR neighbours and move (eq. 13-14), as kernels::move_particle; the largest step of
// settled particles is reduced per subgroup and combined with one atomicMax per subgroup (a
// workgroup barrier would make lavapipe run every invocation as a coroutine).
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_basic : require
#include "solver_common.glsl"

void main() {
  int a = int(gl_GlobalInvocationID.x);
  float settled_step = 0.0f;
  if (a < P.particle_count) {
    vec2 pa = position_in[a];
    vec2 next = pa;
    float step_length = 0.0f;
    if (!solver_done() && particle_moves(stray_count[a])) {
      SpringSums sums = no_spring_sums();
      for (int i = neighbor_start[a]; i < neighbor_start[a + 1]; ++i) {
        int nb = neighbor[i];
        if (stray_count[nb] == kRetired) continue;
        vec2 pb = nearest_image(P.period, position_in[nb], pa);
        int spring = neighbor_spring[i];
        float l = target[spring];
        precise vec2 d = pb - pa;
        float len = length_2d(d);
        if (spring_is_slack(spring_flags[spring], len, l)) continue;
        sums = accumulate_spring(P, sums, pb, d, len, l, nb > a ? 1.0f : -1.0f);
      }
      if (sums.used != 0) {
        vec2 step_vector = particle_step(P, pa, sums);
        precise vec2 moved = vec2(pa.x + step_vector.x, pa.y + step_vector.y);
        next = moved;
        step_length = length_2d(step_vector);
      }
    }
    position_out[a] = next;
    settled_step = stray_count[a] == 0u ? step_length : 0.0f;
  }
  // Steps are >= 0, so their bit patterns order like the floats.
  uint subgroup_max = subgroupMax(floatBitsToUint(settled_step));
  if (subgroupElect() && subgroup_max != 0u) atomicMax(control[kControlMaxStep], subgroup_max);
}
