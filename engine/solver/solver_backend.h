#pragma once
// A backend that runs the section 5 iteration over a SpringSystem: the CPU reference
// (CpuSpringSolver) or the Vulkan compute solver (compute/). The pipeline only sees this
// interface, so engine/ builds without Vulkan and the app chooses the backend by name.
#include "design/design.h"
#include "solver/solver_surface.h"
#include "solver/spring_system.h"

#include <glm/vec2.hpp>

#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace paver {

// Called with the iteration count and the positions; return false to stop. The CPU solver calls
// it after every iteration, a GPU solver after every batch it reads back.
using SolverObserver = std::function<bool(int iteration, const std::vector<glm::vec2>& positions)>;

enum class StopReason { Converged, IterationLimit, Observer };  // Observer: the observer or `stop`
PAVER_ENUM_NAMES(StopReason, {StopReason::Converged, "converged"}, {StopReason::IterationLimit, "iteration limit"},
                 {StopReason::Observer, "stopped"});

struct SolveReport {
  int iterations = 0;
  StopReason reason = StopReason::IterationLimit;
  float last_max_step = 0;     // max |dp dt| of the last iteration over settled particles, map units
  int strays_pulled_back = 0;  // particle lifts that needed a pull back onto the map
  double milliseconds = 0;
  std::string backend;  // which ran it (SpringSolverBackend::backend_name), set by the pipeline
};

class SpringSolverBackend {
 public:
  virtual ~SpringSolverBackend() = default;
  // Runs until converged, the iteration limit, the observer says stop, or `*stop` becomes true
  // (checked every iteration on the CPU, every batch on a GPU; it costs no read-back of
  // positions, unlike an observer). On return the SpringSystem holds the final state
  // (positions, stray counts, hints, filter targets).
  virtual SolveReport solve(const SolverObserver& observer = {}, const std::atomic<bool>* stop = nullptr) = 0;
  virtual std::string_view backend_name() const = 0;
};

// Makes a solver for one system; the system must outlive it.
using SolverFactory = std::function<std::unique_ptr<SpringSolverBackend>(
    const SolverSurface& surface, SpringSystem& system, const SolverParams& params, double spacing)>;

// The CPU reference solver with `threads` threads (0 = all cores).
SolverFactory cpu_solver_factory(int threads = 0);

// `large` for a system of at least `least_particles` particles, else `small`: a GPU's fixed cost
// per solve (uploads, submissions) is more than a small system's whole solve on the CPU.
SolverFactory routed_by_size(SolverFactory small, SolverFactory large, int least_particles);

}  // namespace paver
