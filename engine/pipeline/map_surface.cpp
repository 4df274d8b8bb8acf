#include "pipeline/map_surface.h"

#include "core/input_error.h"
#include "mesh/mesh_loader.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cstdio>
#include <chrono>
#include <vector>

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
  int far_vertex = -1;
  for (const glm::ivec3& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      const double l = glm::length(mesh.positions[a] - mesh.positions[b]);
      lengths.push_back(l);
      if (l > longest) longest = l, far_vertex = a;
    }
  if (lengths.empty()) return;
  std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
  const double median = lengths[lengths.size() / 2];
  if (!(longest > kMaxEdgeOverMedian * median)) return;
  // Of the longest edge's two ends, the stray one is the farther from the median vertex position.
  const glm::ivec3* face = nullptr;
  for (const glm::ivec3& t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      if (t[k] == far_vertex && glm::length(mesh.positions[t[k]] - mesh.positions[t[(k + 1) % 3]]) == longest) face = &t;
  int stray = far_vertex;
  if (face) {
    std::vector<double> xs, ys, zs;
    for (const glm::dvec3& p : mesh.positions) xs.push_back(p.x), ys.push_back(p.y), zs.push_back(p.z);
    const auto middle = [](std::vector<double>& v) {
      std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
      return v[v.size() / 2];
    };
    const glm::dvec3 centre(middle(xs), middle(ys), middle(zs));
    for (int k = 0; k < 3; ++k)
      if (glm::length(mesh.positions[(*face)[k]] - centre) > glm::length(mesh.positions[stray] - centre))
        stray = (*face)[k];
  }
  const glm::dvec3 p = mesh.positions[stray];
  char text[320];
  std::snprintf(text, sizeof text,
                ": an edge is %.3g times longer than the surface's median edge (%.3g): the vertex at "
                "(%.6g, %.6g, %.6g) looks stray; remove it or remesh the surface",
                longest / median, median, p.x, p.y, p.z);
  throw InputError(path.string() + text);
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
  check_surface_proportions(path, loaded.mesh);
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
