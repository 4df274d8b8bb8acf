#include "pipeline/map_surface.h"

#include "core/input_error.h"
#include "mesh/mesh_loader.h"

#include <algorithm>
#include <cstdio>
#include <chrono>

namespace paver {
namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }


}  // namespace

void check_surface_size(const std::filesystem::path& path, const SurfaceMesh& mesh) {
  const double size = bounding_box_diagonal(mesh);
  if (!(size >= kMinSurfaceSize && size <= kMaxSurfaceSize)) {
    char text[64];
    std::snprintf(text, sizeof text, "%.3g", size);
    throw InputError(path.string() + ": the surface is " + text +
                     " units across; the optimizer computes in single precision and handles 1e-6 to 1e9: rescale "
                     "the model (to millimetres, say) and try again");
  }
}

MappedSurface map_surface_file(const std::filesystem::path& path, const PipelineProgress& progress,
                               const StopRequested& stop, const PipelineWarning& warn) {
  const auto report = [&](float fraction, const std::string& stage) {
    if (progress) progress(fraction, stage);
  };
  const auto stopped = [&] { return stop && stop(); };
  MappedSurface out;
  auto t0 = Clock::now();
  report(0.0f, "loading");
  LoadedSurface loaded = load_surface(path);
  out.warnings = std::move(loaded.warnings);
  if (warn)
    for (const std::string& w : out.warnings) warn(w);
  out.timings.emplace_back("load", ms_since(t0));
  check_surface_size(path, loaded.mesh);
  if (stopped()) return out;

  t0 = Clock::now();
  try {
    report(0.05f, "mapping: start map and factorization");
    std::optional<Parameterization> parameterization = parameterize_arap(
        loaded.mesh, ArapOptions{},
        [&](int done, int max, double energy) {
          char text[96];
          std::snprintf(text, sizeof text, "mapping: ARAP %d / %d, energy %.6g", done, max, energy);
          report(0.15f + 0.75f * float(done) / float(max), text);
        },
        stopped);
    if (!parameterization) return out;
    report(0.92f, "mapping: lifting data");
    out.map =
        std::make_shared<const SurfaceMap>(make_surface_map(std::move(loaded.mesh), std::move(*parameterization)));
  } catch (const InputError& e) {
    // The map's own refusals (a Laplacian that cannot be factorized) do not know the file.
    throw InputError(path.string() + ": " + e.what() + "; remesh the surface or remove its sliver triangles");
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(path.string() + ": " + e.what());
  }
  out.timings.emplace_back("parameterize", ms_since(t0));
  report(1.0f, "mapped");
  return out;
}

}  // namespace paver
