#include "surface_loader.h"

#include "core/input_error.h"
#include "pipeline/map_surface.h"

#include <mutex>

namespace paver::studio {

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

SurfaceLoadOutcome load_and_map(const std::filesystem::path& path, CutAxis cut, std::stop_token stop,
                                SurfaceLoader::Shared& shared) {
  SurfaceLoadOutcome outcome;
  try {
    MappedSurface mapped = map_surface_file(
        path, [&](float fraction, const std::string& stage) { shared.report(fraction, stage); },
        [&] { return stop.stop_requested(); }, {}, cut);
    if (!mapped.map) return outcome;  // abandoned
    outcome.surface = OpenedSurface{path, std::move(mapped.map), std::move(mapped.warnings), std::move(mapped.timings)};
  } catch (const InputError& e) {
    outcome.error = e.what();
    outcome.input_error = true;
  } catch (const std::exception& e) {
    outcome.error = e.what();
  }
  return outcome;
}

}  // namespace

void SurfaceLoader::start(const std::filesystem::path& path, CutAxis cut) {
  path_ = path;
  auto shared = std::make_shared<Shared>();
  shared_ = shared;
  jobs_.start([shared, path, cut](std::stop_token stop) {
    SurfaceLoadOutcome outcome = load_and_map(path, cut, stop, *shared);
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
