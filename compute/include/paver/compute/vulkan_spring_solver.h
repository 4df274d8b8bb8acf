#pragma once
// The section 5 iteration as Vulkan compute shaders over SSBOs (shaders/solver_*.comp): per
// iteration a lift pass (per particle), a spring pass (per spring), a move pass (per particle,
// CSR gather, no float atomics) with a per-subgroup max reduction, and a one-invocation pass
// that counts the iteration and tests convergence on the GPU. Many iterations are recorded into
// one submission with barriers between dispatches; once converged, later iterations are no-ops,
// so the result equals the CPU reference's iteration for iteration. The host reads the control
// block back once per batch and the positions only when asked (end, or for an observer).
#include "paver/compute/result.h"
#include "paver/compute/vulkan_context.h"
#include "solver/solver_backend.h"

#include <memory>

namespace paver::gpu {

// Pipelines, descriptor sets and buffers, kept across solves: the surface's buffers are uploaded
// again only when the surface changes, the system's when it changes (each solve), reusing the
// allocations when they are large enough.
class VulkanSolverSession {
public:
  static Result<std::shared_ptr<VulkanSolverSession>> create(std::shared_ptr<VulkanContext> context);
  ~VulkanSolverSession();

  VulkanContext& context();
  int surface_uploads() const;  // how many times surface buffers were (re)uploaded

  struct Impl;
  Impl& impl() { return *impl_; }

private:
  VulkanSolverSession();
  std::unique_ptr<Impl> impl_;
};

// A SolverFactory for the pipeline. `batch`: iterations per submission; convergence and the
// observer are checked between batches (the CPU solver checks the observer every iteration).
SolverFactory vulkan_solver_factory(std::shared_ptr<VulkanSolverSession> session, int batch = 64);

}  // namespace paver::gpu
