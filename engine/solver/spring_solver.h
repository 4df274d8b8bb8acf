#pragma once
// The CPU reference solver of section 5: the iteration of solver_kernels.h over all particles
// and springs, in parallel with TBB. Deterministic: every item is computed independently and in
// a fixed order, so the result is bit-identical whatever the thread count.
#include "design/design.h"
#include "solver/solver_backend.h"
#include "solver/solver_kernels.h"
#include "solver/solver_surface.h"
#include "solver/spring_system.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <tbb/task_arena.h>

#include <cstdint>
#include <memory>
#include <string_view>
#include <vector>

namespace paver {

SolverConstants make_solver_constants(const SolverParams& params, const SolverSurface& surface);

class CpuSpringSolver final : public SpringSolverBackend {
public:
  // `spacing` (D) scales the convergence threshold. threads = 0: all cores.
  CpuSpringSolver(const SolverSurface& surface, SpringSystem& system, const SolverParams& params,
                  double spacing, int threads = 0);

  // One iteration; returns max |dp dt| over settled particles (stray count 0).
  float step();
  SolveReport solve(const SolverObserver& observer = {}, const std::atomic<bool>* stop = nullptr) override;
  std::string_view backend_name() const override { return "cpu"; }


private:
  void lift_all(bool count_strays);
  void update_springs();

  const SolverSurface& surface_;
  SpringSystem& system_;
  SolverParams params_;
  SolverConstants constants_;
  float threshold_;
  int threads_;
  std::unique_ptr<tbb::task_arena> arena_;  // the solver's threads, made once
  int iterations_ = 0;
  int strays_ = 0;
  std::vector<glm::vec3> lifted_;
  std::vector<float> curvature_;
  std::vector<std::uint8_t> pulled_back_;  // #P 1 when the last lift pulled the particle back
  std::vector<glm::vec2> next_;
  std::vector<float> steps_;
};

}  // namespace paver
