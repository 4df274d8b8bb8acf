#version 450
// Pass 4 of an iteration, one invocation: count the iteration and test convergence on the GPU,
// so many iterations run in one submission and later ones become no-ops once it converged.
// Mirrors the loop in CpuSpringSolver::solve.
#extension GL_GOOGLE_include_directive : require
#include "solver_common.glsl"

void main() {
  if (gl_GlobalInvocationID.x != 0u) return;
  if (control[kControlDone] == 0u) {
    control[kControlIterations] += 1u;
    control[kControlLastMaxStep] = control[kControlMaxStep];
    if (uintBitsToFloat(control[kControlMaxStep]) < P.threshold) control[kControlDone] = 1u;
  }
  control[kControlMaxStep] = 0u;
}
