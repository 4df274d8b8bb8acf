#include "pipeline/map_surface.h"
#include "core/number_text.h"

#include "core/input_error.h"
#include "core/stopwatch.h"
#include "mesh/mesh_loader.h"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cstdio>
#include <vector>

namespace paver {
namespace {



}  // namespace

void check_surface_size(const std::filesystem::path& path, const SurfaceMesh& mesh) {
  const double size = bounding_box_diagonal(mesh);
  if (!(size >= kMinSurfaceSize && size <= kMaxSurfaceSize)) {
    throw InputError(path.string() + ": the surface is " + significant_text(size) +
                     " units across; the optimizer computes in single precision and handles 1e-6 to 1e9: rescale "
                     "the model (to millimetres, say) and try again");
  }
}

namespace {
// A stray vertex (one coordinate typed wrong, a scanner's outlier) turns its faces into slivers
// millions of times longer than the rest, which hold most of the area: the map gives them most
// of the plane and the pattern millions of points there. No surface Paver can pave has edges this
// much longer than its typical one, so it is refused naming the vertex.
constexpr double kMaxEdgeOverMedian = 1e5;
}  // namespace

void check_surface_proportions(const std::filesystem::path& path, const SurfaceMesh& mesh) {
  std::vector<double> lengths;
  lengths.reserve(mesh.triangles.size() * 3);
  double longest = 0;
  glm::ivec2 longest_ends(0);
  for (const glm::ivec3& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const glm::ivec2 ends(t[k], t[(k + 1) % 3]);
      lengths.push_back(glm::length(mesh.positions[ends.x] - mesh.positions[ends.y]));
      if (lengths.back() > longest) longest = lengths.back(), longest_ends = ends;
    }
  if (lengths.empty()) return;
  const auto median = [](std::vector<double>& v) {
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
  };
  const double typical = median(lengths);
  if (!(longest > kMaxEdgeOverMedian * typical)) return;
  // Of the longest edge's two ends, the stray one lies farther from the vertices' median position.
  std::vector<double> xs, ys, zs;
  for (const glm::dvec3& p : mesh.positions) xs.push_back(p.x), ys.push_back(p.y), zs.push_back(p.z);
  const glm::dvec3 centre(median(xs), median(ys), median(zs));
  const glm::dvec3 a = mesh.positions[longest_ends.x], b = mesh.positions[longest_ends.y];
  const glm::dvec3 p = glm::length(a - centre) > glm::length(b - centre) ? a : b;
  char text[320];
  std::snprintf(text, sizeof text,
                ": an edge is %.3g times longer than the surface's median edge (%.3g): the vertex at "
                "(%.6g, %.6g, %.6g) looks stray; remove it or remesh the surface",
                longest / typical, typical, p.x, p.y, p.z);
  throw InputError(path.string() + text);
}

std::shared_ptr<const SurfaceMap> map_closed_mesh(const SurfaceMesh& closed, const std::filesystem::path& path,
                                                  CutAxis cut, const PipelineProgress& progress,
                                                  const StopRequested& stop) {
  try {
    std::optional<SurfaceMap> atlas = map_closed_surface(
        closed, cut, path.string(),
        [&](int chart, int charts) {
          if (progress)
            progress(0.05f + 0.9f * float(chart) / float(charts),
                     "mapping: chart " + std::to_string(chart + 1) + " of " + std::to_string(charts));
        },
        [&] { return stop && stop(); });
    if (!atlas) return nullptr;
    return std::make_shared<const SurfaceMap>(std::move(*atlas));
  } catch (const InputError&) {
    throw;  // names the file and the chart already
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(path.string() + ": " + e.what());
  }
}

LoadedSurface load_checked_surface(const std::filesystem::path& path, const PipelineWarning& warn,
                                   const std::vector<std::string>& region) {
  LoadedSurface loaded = load_surface(path, region);
  if (warn)
    for (const std::string& w : loaded.warnings) warn(w);
  check_surface_size(path, loaded.mesh);
  check_surface_proportions(path, loaded.mesh);
  return loaded;
}

MappedSurface map_surface_file(const std::filesystem::path& path, const PipelineProgress& progress,
                               const StopRequested& stop, const PipelineWarning& warn, CutAxis cut,
                               const std::function<void(const SurfaceMesh&)>& check_loaded,
                               const std::vector<std::string>& region) {
  const auto report = [&](float fraction, const std::string& stage) {
    if (progress) progress(fraction, stage);
  };
  const auto stopped = [&] { return stop && stop(); };
  MappedSurface out;
  Stopwatch watch;
  report(0.0f, "loading");
  LoadedSurface loaded = load_checked_surface(path, warn, region);
  out.warnings = std::move(loaded.warnings);
  out.timings.emplace_back("load", watch.milliseconds());
  if (check_loaded) check_loaded(loaded.mesh);
  if (stopped()) return out;

  watch = Stopwatch();
  if (loaded.mesh.boundary_loops.empty()) {
    out.closed_surface = std::make_shared<const SurfaceMesh>(std::move(loaded.mesh));
    out.map = map_closed_mesh(*out.closed_surface, path, cut, progress, stop);
    if (!out.map) return out;
    out.timings.emplace_back("parameterize", watch.milliseconds());
    report(1.0f, "mapped");
    return out;
  }
  try {
    report(0.05f, "mapping: start map and factorization");
    std::optional<Parameterization> parameterization = parameterize_surface(
        loaded.mesh, map_options_for(loaded.mesh),
        [&](int done, int max, double energy) {
          report(0.15f + 0.75f * float(done) / float(max), "mapping: " + map_progress_text(done, max, energy));
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
  out.timings.emplace_back("parameterize", watch.milliseconds());
  report(1.0f, "mapped");
  return out;
}

}  // namespace paver
