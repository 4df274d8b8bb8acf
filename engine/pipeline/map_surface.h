#pragma once
// Stages 1-2 of the pipeline: a surface file, loaded and checked (mesh/), mapped bijectively to
// the plane (map/). run_pipeline (so `paver run`) and the studio's background loader call this;
// `paver param`, which exposes the map's own options, loads through load_checked_surface and
// calls the map stage's functions itself.
#include "map/surface_charts.h"
#include "mesh/mesh_loader.h"
#include "map/surface_map.h"
#include "pipeline/pavement.h"

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace paver {

// Progress of a long stage: fraction of the whole call in [0, 1] and what it is doing.
using PipelineProgress = std::function<void(float fraction, const std::string& stage)>;
// Polled between chunks of work; true abandons the call.
using StopRequested = std::function<bool()>;
// A repair the loader made (dropped faces, components), told as soon as it is known.
using PipelineWarning = std::function<void(const std::string&)>;

// The sizes (bounding-box diagonal, surface units) the pipeline accepts: the solver works in float32,
// whose squared lengths overflow or lose all precision far outside them.
inline constexpr double kMinSurfaceSize = 1e-6, kMaxSurfaceSize = 1e9;
// Throws InputError naming `path` when the mesh's size is outside [kMinSurfaceSize, kMaxSurfaceSize].
void check_surface_size(const std::filesystem::path& path, const SurfaceMesh& mesh);
// Refuses a surface with an edge 1e5 times longer than its median edge (a stray vertex), naming
// the vertex's position: its slivers would take most of the map and millions of pattern points.
void check_surface_proportions(const std::filesystem::path& path, const SurfaceMesh& mesh);

struct MappedSurface {
  std::shared_ptr<const SurfaceMap> map;  // null when stopped
  std::vector<std::string> warnings;      // the loader's repairs (dropped faces, components)
  StageTimings timings;                   // "load", "parameterize"
  // A closed surface as loaded and checked, to be cut across another axis (map_closed_mesh)
  // without reading the file again; null for an open surface.
  std::shared_ptr<const SurfaceMesh> closed_surface;
};

// A closed surface, loaded from `path`, cut across `cut` and mapped as an atlas; null when
// stopped. Errors name `path`.
std::shared_ptr<const SurfaceMap> map_closed_mesh(const SurfaceMesh& closed, const std::filesystem::path& path,
                                                  CutAxis cut, const PipelineProgress& progress = {},
                                                  const StopRequested& stop = {});

// Stage 1: the surface loaded (mesh/mesh_loader.h), its repairs told to `warn`, and checked
// (size, a stray vertex): what every command that reads a surface reads it through.
// `region`: the named parts to keep (mesh/mesh_loader.h), all when empty.
LoadedSurface load_checked_surface(const std::filesystem::path& path, const PipelineWarning& warn = {},
                                   const std::vector<std::string>& region = {});

// Throws InputError for a file Paver cannot pave (naming the file), std::runtime_error naming the
// file when the map fails.
// A closed surface is cut into charts across `cut` (map/surface_charts.h) and mapped as their atlas.
// `check_loaded` sees the surface once it is loaded and checked, before the map: the caller's
// refusals that need only the surface (a spacing far too small for its area) cost no map.
MappedSurface map_surface_file(const std::filesystem::path& path, const PipelineProgress& progress = {},
                               const StopRequested& stop = {}, const PipelineWarning& warn = {},
                               CutAxis cut = CutAxis::Auto,
                               const std::function<void(const SurfaceMesh&)>& check_loaded = {},
                               const std::vector<std::string>& region = {});

}  // namespace paver
