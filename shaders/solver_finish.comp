#version 450
// Pass 4 of an iteration, one invocation: count the iteration and test convergence on the GPU,
// so many iterations run in one submission and later ones become no-ops once it converged.
// Mirrors the loop in CpuSpringSolver::solve.
#extension GL_GOOGLE_include_directive : require
#include "solver_common.glsl"

void main() {
  if (gl_GlobalInvocationID.x != 0u) return;
  if (control[0] == 0u) {
    control[1] += 1u;
    control[5] = control[3];
    if (uintBitsToFloat(control[3]) < P.threshold) control[0] = 1u;
  }
  control[3] = 0u;
}
