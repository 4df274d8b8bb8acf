#pragma once
// Host mirror of the solver's std140 parameter block (shaders/solver_common.glsl, `Params`).
#include <cstddef>
#include <cstdint>

namespace paver::gpu {

struct alignas(16) GpuSolverParams {
  float c, m, alpha, beta;
  float gamma, lambda_r, lambda_l, lambda_g;
  float dt, mu_compressed, mu_stretched, filter_max;
  float curvature_min, curvature_inv_range, threshold, grid_cell_size;
  float centre[2], grid_origin[2];
  std::int32_t grid_nx, grid_ny, boundary_count, particle_count;
  std::int32_t spring_count;
  std::uint32_t filter_base_initial, stray_patience, pad0;
};
static_assert(sizeof(GpuSolverParams) == 112);
static_assert(offsetof(GpuSolverParams, dt) == 32);
static_assert(offsetof(GpuSolverParams, curvature_min) == 48);
static_assert(offsetof(GpuSolverParams, centre) == 64);
static_assert(offsetof(GpuSolverParams, grid_origin) == 72);
static_assert(offsetof(GpuSolverParams, grid_nx) == 80);
static_assert(offsetof(GpuSolverParams, spring_count) == 96);
static_assert(offsetof(GpuSolverParams, stray_patience) == 104);

// The control block (binding 24): indices into control[].
enum ControlSlot : std::uint32_t {
  kControlDone = 0,
  kControlIterations = 1,
  kControlStrays = 2,
  kControlMaxStep = 3,
  kControlError = 4,
  kControlLastMaxStep = 5,
  kControlSlots = 8,
};

// Bits of control[kControlError], as kErrorNonFinite / kErrorNotLifted in solver_common.glsl.
constexpr std::uint32_t kErrorNonFinite = 1u;
constexpr std::uint32_t kErrorNotLifted = 2u;

// Bindings of the solver's descriptor set, as in solver_common.glsl.
enum Binding : std::uint32_t {
  kParams = 0, kUv, kSurfacePosition, kSurfaceCurvature, kTriangles, kGridStart, kGridTriangles, kBoundaryUv,
  kBoundaryInward, kPositionIn, kPositionOut, kStrayCount, kTriangleHint, kPulledBack, kLifted, kNeighborStart,
  kNeighbor, kNeighborSpring, kSpringA, kSpringB, kRestLength, kSpringFlags, kTarget, kInitialTarget, kControl,
  kBindingCount
};

}  // namespace paver::gpu
