// Shared by the solver's compute shaders: the buffers (one descriptor set for all passes) and the
// parameter block, laid out by engine/solver/solver_contract.h, whose arithmetic the passes call:
// the CPU reference (engine/solver/solver_kernels.h) calls the same functions, so on a device
// with IEEE float32 arithmetic the GPU computes exactly what the CPU computes. What the passes
// write themselves is the walk over the buffers, in the CPU's order.
#extension GL_GOOGLE_include_directive : require
#include "solver/solver_contract.h"

layout(local_size_x = kSolverGroupSize) in;

layout(std140, set = 0, binding = kBindingParams) uniform ParamsBlock { SolverConstants P; };
layout(push_constant) uniform PushBlock { SolverPush pc; };

layout(std430, set = 0, binding = kBindingUv) readonly buffer Uv { vec2 uv[]; };
layout(std430, set = 0, binding = kBindingSurfacePosition) readonly buffer SurfacePosition { vec4 surface_position[]; };
layout(std430, set = 0, binding = kBindingSurfaceCurvature) readonly buffer SurfaceCurvature { float surface_curvature[]; };
layout(std430, set = 0, binding = kBindingTriangles) readonly buffer Triangles { int triangles[]; };
layout(std430, set = 0, binding = kBindingGridStart) readonly buffer GridStart { int grid_start[]; };
layout(std430, set = 0, binding = kBindingGridTriangles) readonly buffer GridTriangles { int grid_triangles[]; };
layout(std430, set = 0, binding = kBindingBoundarySegments) readonly buffer BoundarySegments { vec4 boundary_segments[]; };
layout(std430, set = 0, binding = kBindingBoundaryInward) readonly buffer BoundaryInward { vec2 boundary_inward[]; };
layout(std430, set = 0, binding = kBindingPositionIn) buffer PositionIn { vec2 position_in[]; };
layout(std430, set = 0, binding = kBindingPositionOut) buffer PositionOut { vec2 position_out[]; };
layout(std430, set = 0, binding = kBindingStrayCount) buffer StrayCount { uint stray_count[]; };
layout(std430, set = 0, binding = kBindingTriangleHint) buffer TriangleHint { int triangle_hint[]; };
layout(std430, set = 0, binding = kBindingPulledBack) buffer PulledBack { uint pulled_back[]; };
layout(std430, set = 0, binding = kBindingLifted) buffer Lifted { vec4 lifted[]; };
layout(std430, set = 0, binding = kBindingNeighborStart) readonly buffer NeighborStart { int neighbor_start[]; };
layout(std430, set = 0, binding = kBindingNeighbor) readonly buffer Neighbor { int neighbor[]; };
layout(std430, set = 0, binding = kBindingNeighborSpring) readonly buffer NeighborSpring { int neighbor_spring[]; };
layout(std430, set = 0, binding = kBindingSpringA) readonly buffer SpringA { int spring_a[]; };
layout(std430, set = 0, binding = kBindingSpringB) readonly buffer SpringB { int spring_b[]; };
layout(std430, set = 0, binding = kBindingRestLength) readonly buffer RestLength { float rest_length[]; };
layout(std430, set = 0, binding = kBindingSpringFlags) readonly buffer SpringFlags { uint spring_flags[]; };
layout(std430, set = 0, binding = kBindingTarget) buffer Target { float target[]; };
layout(std430, set = 0, binding = kBindingInitialTarget) buffer InitialTarget { float initial_target[]; };
layout(std430, set = 0, binding = kBindingControl) buffer Control { uint control[]; };
layout(std430, set = 0, binding = kBindingBoundaryGridStart) readonly buffer BoundaryGridStart { int boundary_grid_start[]; };
layout(std430, set = 0, binding = kBindingBoundaryGridSegments) readonly buffer BoundaryGridSegments { int boundary_grid_segments[]; };

bool solver_done() { return control[kControlDone] != 0u; }
