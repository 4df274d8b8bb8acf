#include "solver/spring_solver.h"

#include "core/stopwatch.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>
#include <string>

namespace paver {
namespace {

// Small systems run in one chunk: the per-iteration task overhead would dominate.
constexpr std::size_t kGrain = 2048;

template <class F>
void for_each_index(int n, F&& f) {
  tbb::parallel_for(tbb::blocked_range<int>(0, n, kGrain), [&](const tbb::blocked_range<int>& r) {
    for (int i = r.begin(); i != r.end(); ++i) f(i);
  });
}

}  // namespace

SolverFactory cpu_solver_factory(int threads) {
  return [threads](const SolverSurface& surface, SpringSystem& system, const SolverParams& params, double spacing) {
    return std::unique_ptr<SpringSolverBackend>(new CpuSpringSolver(surface, system, params, spacing, threads));
  };
}

SolverFactory routed_by_size(SolverFactory small, SolverFactory large, int least_particles) {
  return [small = std::move(small), large = std::move(large), least_particles](
             const SolverSurface& surface, SpringSystem& system, const SolverParams& params, double spacing) {
    return system.particle_count() >= least_particles ? large(surface, system, params, spacing)
                                                      : small(surface, system, params, spacing);
  };
}

SolverConstants make_solver_constants(const SolverParams& p, const SolverSurface& surface) {
  SolverConstants k{};
  k.c = float(p.c), k.m = float(p.m);
  k.alpha = float(p.alpha), k.beta = float(p.beta), k.gamma = float(p.gamma);
  k.lambda_r = float(p.lambda_r), k.lambda_l = float(p.lambda_l), k.lambda_g = float(p.lambda_g);
  k.dt = float(p.dt);
  k.mu_compressed = float(p.mu_compressed), k.mu_stretched = float(p.mu_stretched);
  k.filter_max = float(p.filter_max);
  k.curvature_min = surface.curvature_min;
  const float range = surface.curvature_max - surface.curvature_min;
  // A surface of constant curvature has no variation to follow: every edge gets m * 0.
  k.curvature_inv_range = range > 0.0f ? 1.0f / range : 0.0f;
  k.centre = surface.centre;
  k.filter_base_initial = p.filter_base == FilterBase::Initial ? 1u : 0u;
  k.stray_patience = std::uint32_t(p.stray_patience);
  k.period = surface.period;
  k.period_origin = surface.period_origin;
  return k;
}

CpuSpringSolver::CpuSpringSolver(const SolverSurface& surface, SpringSystem& system,
                                 const SolverParams& params, double spacing, int threads)
    : surface_(surface),
      system_(system),
      params_(params),
      constants_(make_solver_constants(params, surface)),
      threshold_(float(params.threshold * spacing)),
      // More threads than cores would gain nothing, and TBB warns on stderr about each one it refuses.
      threads_(threads > 0 ? std::min(threads, tbb::this_task_arena::max_concurrency())
                           : tbb::this_task_arena::max_concurrency()) {
  const int n = system.particle_count();
  lifted_.resize(n);
  pulled_back_.assign(n, 0);
  curvature_.resize(n);
  next_.resize(n);
  steps_.resize(n);
  arena_ = std::make_unique<tbb::task_arena>(threads_);
  arena_->execute([&] {
    lift_all(true);
    update_springs();
  });
}

void CpuSpringSolver::lift_all(bool count_strays) {
  std::atomic<int> strays{0};
  for_each_index(system_.particle_count(), [&](int a) {
    const glm::vec2 before = system_.position[a];
    // A non-finite position would be hidden by the pull back (it lands on a boundary triangle).
    if (!std::isfinite(before.x) || !std::isfinite(before.y))
      throw std::runtime_error("solver: particle " + std::to_string(a) + " has a non-finite position");
    const kernels::LiftedParticle l =
        kernels::lift_particle(surface_, system_.position[a], system_.triangle_hint[a]);
    if (std::isnan(l.position.x)) throw std::runtime_error("solver: a particle could not be lifted");
    lifted_[a] = l.position;
    curvature_[a] = l.curvature;
    // The closing lift of solve() only refreshes the lifted state; it is not an iteration.
    if (!count_strays) return;
    // Wrapping into the period is not a pull back.
    const bool pulled = system_.position[a] != wrap_position(surface_.period, surface_.period_origin, before);
    pulled_back_[a] = pulled ? 1 : 0;
    system_.stray_count[a] = next_stray_count(constants_, system_.stray_count[a], pulled);
    if (pulled) strays.fetch_add(1, std::memory_order_relaxed);
  });
  strays_ += strays.load();
}

void CpuSpringSolver::update_springs() {
  for_each_index(system_.spring_count(), [&](int s) {
    const int a = system_.spring_a[s], b = system_.spring_b[s];
    // A spring without a target (a new system, or a contact spring just added) starts from the
    // unfiltered target, which is also its l_ab at initialisation.
    const bool fresh = system_.target[s] <= 0.0f;
    const SpringState st = update_spring(
        constants_, nearest_image(constants_.period, system_.position[b], system_.position[a]) - system_.position[a],
        lifted_[b] - lifted_[a], curvature_[a],
        curvature_[b], system_.rest_length[s], system_.target[s], system_.initial_target[s],
        fresh || pulled_back_[a] != 0 || pulled_back_[b] != 0, system_.spring_flags[s]);
    system_.target[s] = st.target;
    if (fresh) system_.initial_target[s] = st.target;
  });
}

float CpuSpringSolver::step() {
  float max_step = 0;
  arena_->execute([&] {
    if (iterations_ > 0) {
      lift_all(true);
      update_springs();
    }
    for_each_index(system_.particle_count(), [&](int a) {
      const kernels::Move mv = kernels::move_particle(constants_, system_, a, system_.position);
      next_[a] = mv.position;
      // Convergence looks at settled particles: one being pulled back onto the boundary (or
      // retired) is in transit and would keep the maximum up without changing the pattern.
      steps_[a] = system_.stray_count[a] == 0u ? mv.step : 0.0f;
    });
  });
  system_.position.swap(next_);
  for (float s : steps_) max_step = std::max(max_step, s);
  ++iterations_;
  return max_step;
}

SolveReport CpuSpringSolver::solve(const SolverObserver& observer, const std::atomic<bool>* stop) {
  const Stopwatch watch;
  SolveReport report;
  report.reason = StopReason::IterationLimit;
  for (int it = 0; it < params_.iterations; ++it) {
    report.last_max_step = step();
    report.iterations = it + 1;
    if ((observer && !observer(report.iterations, system_.position)) || (stop && stop->load())) {
      report.reason = StopReason::Observer;
      break;
    }
    if (report.last_max_step < threshold_) {
      report.reason = StopReason::Converged;
      break;
    }
  }
  // Leave the positions as lifted (strays pulled back), without another filter step.
  arena_->execute([&] { lift_all(false); });
  report.strays_pulled_back = strays_;
  report.milliseconds = watch.milliseconds();
  return report;
}

}  // namespace paver
