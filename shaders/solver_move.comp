#version 450
// Pass 3 of an iteration, per particle: gather R (eq. 7-9), L (eq. 10-11 with p_b), G (eq. 12)
// over the CSR neighbours and move (eq. 13-14); the largest step of settled particles is reduced
// per subgroup and combined with one atomicMax per subgroup (a workgroup barrier would make
// lavapipe run every invocation as a coroutine). Mirrors kernels::move_particle.
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_basic : require
#include "solver_common.glsl"

float spring_constant(float r) {
  precise float r2 = r * r;
  precise float r6 = r2 * r2 * r2;
  precise float r12 = r6 * r6;
  precise float k = P.alpha / r12 - P.beta / r6 + P.gamma;
  return k;
}

void main() {
  int a = int(gl_GlobalInvocationID.x);
  float settled_step = 0.0;
  if (a < P.particle_count) {
    vec2 pa = position_in[a];
    vec2 next = pa;
    float step_length = 0.0;
    if (!solver_done() && stray_count[a] != kRetired) {
      precise vec2 force = vec2(0.0);
      precise vec2 centroid_sum = vec2(0.0);
      precise float k_sum = 0.0, w_sum = 0.0, stretch_sum = 0.0;
      int used = 0;
      int begin = neighbor_start[a], end = neighbor_start[a + 1];
      for (int i = begin; i < end; ++i) {
        int nb = neighbor[i];
        if (stray_count[nb] == kRetired) continue;
        vec2 pb = position_in[nb];
        int spring = neighbor_spring[i];
        float l = target[spring];
        precise vec2 d = pb - pa;
        precise float len = sqrt(d.x * d.x + d.y * d.y);
        if ((spring_flags[spring] & kSpringContact) != 0u && len >= l) continue;
        ++used;
        precise float ratio = len / l;
        float kc = spring_constant(max_f(ratio, 0.1));
        precise float tiny = 1e-6 * l;
        precise vec2 unit = len > tiny ? vec2(d.x / len, d.y / len) : vec2(nb > a ? 1.0 : -1.0, 0.0);
        precise float f = kc * (len - l);
        force = vec2(force.x + f * unit.x, force.y + f * unit.y);
        k_sum = k_sum + kc;
        centroid_sum = vec2(centroid_sum.x + pb.x / l, centroid_sum.y + pb.y / l);
        w_sum = w_sum + 1.0 / l;
        stretch_sum = stretch_sum + (len - l);
      }
      if (used != 0) {
        precise vec2 restoring = vec2(force.x / k_sum, force.y / k_sum);
        precise vec2 local_force = vec2(centroid_sum.x / w_sum - pa.x, centroid_sum.y / w_sum - pa.y);
        precise vec2 to_centre = P.centre - pa;
        precise float centre_dist = sqrt(to_centre.x * to_centre.x + to_centre.y * to_centre.y);
        precise float g = centre_dist > 0.0 ? stretch_sum / float(used) / centre_dist : 0.0;
        precise vec2 global_force = vec2(g * to_centre.x, g * to_centre.y);
        precise vec2 dp = vec2(P.lambda_r * restoring.x + P.lambda_l * local_force.x + P.lambda_g * global_force.x,
                               P.lambda_r * restoring.y + P.lambda_l * local_force.y + P.lambda_g * global_force.y);
        precise vec2 step_vector = vec2(dp.x * P.dt, dp.y * P.dt);
        next = vec2(pa.x + step_vector.x, pa.y + step_vector.y);
        precise float len_step = sqrt(step_vector.x * step_vector.x + step_vector.y * step_vector.y);
        step_length = len_step;
      }
    }
    position_out[a] = next;
    settled_step = stray_count[a] == 0u ? step_length : 0.0;
  }
  // Steps are >= 0, so their bit patterns order like the floats.
  uint subgroup_max = subgroupMax(floatBitsToUint(settled_step));
  if (subgroupElect() && subgroup_max != 0u) atomicMax(control[3], subgroup_max);
}
