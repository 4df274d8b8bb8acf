#include "surface_loader.h"

#include "map/arap_parameterization.h"
#include "core/input_error.h"
#include "map/map_quality.h"
#include "mesh/mesh_loader.h"

#include <glm/geometric.hpp>

#include <chrono>
#include <cmath>
#include <mutex>

namespace paver::studio {

namespace {
using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

constexpr int kIterationsPerChunk = 4;  // a few ms each on a dense mesh: the progress moves smoothly
}  // namespace

struct SurfaceLoader::Shared {
  mutable std::mutex mutex;
  float progress = 0;
  std::string stage = "loading";
  std::optional<SurfaceLoadOutcome> outcome;

  void report(float p, std::string s) {
    std::lock_guard lock(mutex);
    progress = p;
    stage = std::move(s);
  }
};

namespace {

SurfaceLoadOutcome load_and_map(const std::filesystem::path& path, std::stop_token stop, SurfaceLoader::Shared& shared) {
  SurfaceLoadOutcome outcome;
  try {
    OpenedSurface opened;
    opened.path = path;
    auto t0 = Clock::now();
    LoadedSurface loaded = load_surface(path);
    opened.warnings = loaded.warnings;
    opened.timings.emplace_back("load", ms_since(t0));
    if (stop.stop_requested()) return outcome;

    t0 = Clock::now();
    shared.report(0.05f, "mapping: start map and factorization");
    const ArapOptions options;  // the CLI's defaults
    ArapSolver solver(loaded.mesh, options);
    while (solver.report().iterations < options.max_iterations) {
      if (stop.stop_requested()) return outcome;
      const int chunk = std::min(kIterationsPerChunk, options.max_iterations - solver.report().iterations);
      if (solver.iterate(chunk)) break;
      const int done = solver.report().iterations;
      shared.report(0.15f + 0.75f * float(done) / float(options.max_iterations),
                    "mapping: ARAP " + std::to_string(done) + " / " + std::to_string(options.max_iterations));
    }
    shared.report(0.92f, "mapping: lifting data");
    Parameterization parameterization = finish_parameterization(loaded.mesh, solver);
    opened.map = std::make_shared<SurfaceMap>(make_surface_map(std::move(loaded.mesh), std::move(parameterization)));
    opened.timings.emplace_back("parameterize", ms_since(t0));
    outcome.surface = std::move(opened);
  } catch (const InputError& e) {
    outcome.error = e.what();
  } catch (const std::exception& e) {
    outcome.error = path.string() + ": " + e.what();
  }
  return outcome;
}

}  // namespace

void SurfaceLoader::start(const std::filesystem::path& path) {
  auto shared = std::make_shared<Shared>();
  shared_ = shared;
  jobs_.start([shared, path](std::stop_token stop) {
    SurfaceLoadOutcome outcome = load_and_map(path, stop, *shared);
    std::lock_guard lock(shared->mutex);
    shared->progress = 1;
    shared->outcome = std::move(outcome);
  });
}

bool SurfaceLoader::busy() const {
  if (!shared_) return false;
  std::lock_guard lock(shared_->mutex);
  return !shared_->outcome;
}

float SurfaceLoader::progress() const {
  if (!shared_) return 0;
  std::lock_guard lock(shared_->mutex);
  return shared_->progress;
}

std::string SurfaceLoader::stage() const {
  if (!shared_) return {};
  std::lock_guard lock(shared_->mutex);
  return shared_->stage;
}

std::optional<SurfaceLoadOutcome> SurfaceLoader::take_outcome() {
  jobs_.reap();
  if (!shared_) return std::nullopt;
  std::optional<SurfaceLoadOutcome> outcome;
  {
    std::lock_guard lock(shared_->mutex);
    outcome = std::move(shared_->outcome);
  }
  if (outcome) shared_.reset();
  return outcome;
}

}  // namespace paver::studio
