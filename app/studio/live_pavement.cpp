#include "live_pavement.h"

#include <tbb/task_arena.h>

#include <algorithm>
#include <thread>

#include "core/input_error.h"
#include "core/stopwatch.h"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <utility>

namespace paver::studio {
namespace {

using Clock = std::chrono::steady_clock;
// Copying the positions every iteration of a big pattern would cost more than the iteration.
constexpr auto kPublishInterval = std::chrono::milliseconds(30);

}  // namespace

struct LivePavement::Run {
  std::mutex mutex;
  std::condition_variable wake;
  std::atomic<bool> cancelled = false;
  bool paused = false;
  int pause_at = 0;     // pause once the solver reaches this iteration (0: no step pending)
  int iteration = 0;
  LiveSnapshot snapshot;
  Clock::time_point last_publish;
  bool finished = false;
  std::optional<RunOutcome> outcome;  // until taken

  void publish(const std::vector<glm::vec2>& positions) {  // with `mutex` held
    snapshot.points.assign(positions.begin(), positions.end());
    snapshot.iteration = iteration;
    ++snapshot.sequence;
    last_publish = Clock::now();
  }

  // After every solver iteration of the main solve: publish, then wait while paused.
  bool observe(int it, const std::vector<glm::vec2>& positions) {
    std::unique_lock lock(mutex);
    iteration = it;
    // An iteration target, not a count of calls: the Vulkan solver reports once per batch.
    if (pause_at > 0 && it >= pause_at) paused = true, pause_at = 0;
    if (paused || Clock::now() - last_publish > kPublishInterval) publish(positions);
    wake.wait(lock, [&] { return !paused || cancelled; });
    return !cancelled;
  }
};

namespace {

void run_pavement(const RunRequest& request, const std::shared_ptr<LivePavement::Run>& run) {
  const Stopwatch watch;
  RunOutcome outcome;
  outcome.revision = request.revision;
  try {
    PipelineRequest pipeline;
    pipeline.map = request.map;
    pipeline.design = request.design;
    pipeline.design_source = "studio";
    pipeline.custom_shape = request.custom_shape;
    PavementOptions& options = pipeline.pavement;
    options.solver = request.solver;  // empty: the CPU reference
    options.stop = &run->cancelled;   // every solve of the run, the collision resolution's too
    // The live view starts from the pattern before the solver moves it.
    options.on_pattern = [&](const Pattern& pattern, const Design& design) {
      std::lock_guard lock(run->mutex);
      run->snapshot.revision = request.revision;
      run->snapshot.pattern = std::make_shared<const Pattern>(pattern);
      run->snapshot.design = design;
      run->snapshot.points = pattern.points;
      ++run->snapshot.sequence;
    };
    options.observer = [run](int it, const std::vector<glm::vec2>& positions) { return run->observe(it, positions); };
    // One core is left to the UI thread, so that the window keeps its pace while the run solves
    // (on 2 cores with a software renderer it fell to 11 fps with every core solving).
    tbb::task_arena arena(std::max(1, int(std::thread::hardware_concurrency()) - 1));
    arena.execute(
        [&] { outcome.pavement = std::make_shared<const Pavement>(run_pipeline(std::move(pipeline)).pavement); });
  } catch (const InputError& e) {
    outcome.error = e.what();
    outcome.input_error = true;
  } catch (const std::exception& e) {
    outcome.error = std::string("the pavement failed: ") + e.what();
  }
  outcome.milliseconds = watch.milliseconds();
  std::lock_guard lock(run->mutex);
  run->finished = true;
  if (!run->cancelled) run->outcome = std::move(outcome);
}

}  // namespace

void LivePavement::start(RunRequest request) {
  reset();
  auto run = std::make_shared<Run>();
  // Sequences grow across runs, so the view never takes a new run's snapshot for an old one.
  run->snapshot.sequence = ++runs_started_ << 32;
  run->paused = request.paused;
  run->pause_at = request.paused ? request.step : 0;
  if (run->pause_at > 0) run->paused = false;
  run_ = run;
  revision_ = request.revision;
  jobs_.start([request = std::move(request), run](std::stop_token) { run_pavement(request, run); });
}

void LivePavement::pause() {
  if (!run_) return;
  std::lock_guard lock(run_->mutex);
  run_->paused = true;
}

void LivePavement::resume() {
  if (!run_) return;
  {
    std::lock_guard lock(run_->mutex);
    run_->paused = false;
    run_->pause_at = 0;
  }
  run_->wake.notify_all();
}

void LivePavement::step(int iterations) {
  if (!run_) return;
  {
    std::lock_guard lock(run_->mutex);
    run_->pause_at = run_->iteration + std::max(1, iterations);
    run_->paused = false;
  }
  run_->wake.notify_all();
}

LivePavement::~LivePavement() { reset(); }

void LivePavement::reset() {
  if (run_) {
    {
      std::lock_guard lock(run_->mutex);
      run_->cancelled = true;
    }
    run_->wake.notify_all();
    run_.reset();
  }
  jobs_.reap();
}

RunState LivePavement::state() const {
  if (!run_) return RunState::Idle;
  std::lock_guard lock(run_->mutex);
  if (run_->finished) return RunState::Finished;
  return run_->paused ? RunState::Paused : RunState::Running;
}

std::uint64_t LivePavement::revision() const { return revision_; }

int LivePavement::iteration() const {
  if (!run_) return 0;
  std::lock_guard lock(run_->mutex);
  return run_->iteration;
}

std::optional<LiveSnapshot> LivePavement::snapshot_since(std::uint64_t sequence) const {
  if (!run_) return std::nullopt;
  std::lock_guard lock(run_->mutex);
  if (run_->snapshot.sequence <= sequence || !run_->snapshot.pattern) return std::nullopt;
  return run_->snapshot;
}

std::optional<RunOutcome> LivePavement::take_outcome() {
  jobs_.reap();
  if (!run_) return std::nullopt;
  std::lock_guard lock(run_->mutex);
  return std::exchange(run_->outcome, std::nullopt);
}

}  // namespace paver::studio
