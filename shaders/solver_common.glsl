// Shared by the solver's compute shaders: the buffers (one descriptor set for all passes), the
// parameter block, and the helpers. Every function mirrors engine/solver/solver_kernels.h
// line by line, with `precise` temporaries so no operation is fused or reordered: on a device
// with IEEE float32 arithmetic the GPU then computes exactly what the CPU reference computes.

layout(local_size_x = 64) in;

// std140 mirror: compute/src/gpu_solver_layout.h (static_asserts on size and offsets).
layout(std140, set = 0, binding = 0) uniform Params {
  float c, m, alpha, beta;
  float gamma, lambda_r, lambda_l, lambda_g;
  float dt, mu_compressed, mu_stretched, filter_max;
  float curvature_min, curvature_inv_range, threshold, grid_cell_size;
  vec2 centre, grid_origin;
  int grid_nx, grid_ny, boundary_count, particle_count;
  int spring_count;
  uint filter_base_initial, stray_patience, pad0;
} P;

layout(std430, set = 0, binding = 1) readonly buffer Uv { vec2 uv[]; };
layout(std430, set = 0, binding = 2) readonly buffer SurfacePosition { vec4 surface_position[]; };
layout(std430, set = 0, binding = 3) readonly buffer SurfaceCurvature { float surface_curvature[]; };
layout(std430, set = 0, binding = 4) readonly buffer Triangles { int triangles[]; };
layout(std430, set = 0, binding = 5) readonly buffer GridStart { int grid_start[]; };
layout(std430, set = 0, binding = 6) readonly buffer GridTriangles { int grid_triangles[]; };
layout(std430, set = 0, binding = 7) readonly buffer BoundaryUv { vec2 boundary_uv[]; };
layout(std430, set = 0, binding = 8) readonly buffer BoundaryInward { vec2 boundary_inward[]; };
layout(std430, set = 0, binding = 9) buffer PositionIn { vec2 position_in[]; };
layout(std430, set = 0, binding = 10) buffer PositionOut { vec2 position_out[]; };
layout(std430, set = 0, binding = 11) buffer StrayCount { uint stray_count[]; };
layout(std430, set = 0, binding = 12) buffer TriangleHint { int triangle_hint[]; };
layout(std430, set = 0, binding = 13) buffer PulledBack { uint pulled_back[]; };
layout(std430, set = 0, binding = 14) buffer Lifted { vec4 lifted[]; };  // xyz position, w curvature
layout(std430, set = 0, binding = 15) readonly buffer NeighborStart { int neighbor_start[]; };
layout(std430, set = 0, binding = 16) readonly buffer Neighbor { int neighbor[]; };
layout(std430, set = 0, binding = 17) readonly buffer NeighborSpring { int neighbor_spring[]; };
layout(std430, set = 0, binding = 18) readonly buffer SpringA { int spring_a[]; };
layout(std430, set = 0, binding = 19) readonly buffer SpringB { int spring_b[]; };
layout(std430, set = 0, binding = 20) readonly buffer RestLength { float rest_length[]; };
layout(std430, set = 0, binding = 21) readonly buffer SpringFlags { uint spring_flags[]; };
layout(std430, set = 0, binding = 22) buffer Target { float target[]; };
layout(std430, set = 0, binding = 23) buffer InitialTarget { float initial_target[]; };
// control[0] done, [1] iterations run, [2] pull backs, [3] this iteration's max step (float
// bits; steps are >= 0 so uint order is float order), [4] error bits, [5] last max step.
layout(std430, set = 0, binding = 24) buffer Control { uint control[]; };

const uint kRetired = 0xffffffffu;
const uint kSpringContact = 2u;
const uint kErrorNonFinite = 1u;
const uint kErrorNotLifted = 2u;

bool solver_done() { return control[0] != 0u; }

float min_f(float a, float b) { return b < a ? b : a; }
float max_f(float a, float b) { return a < b ? b : a; }
