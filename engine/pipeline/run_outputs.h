#pragma once
// The files a pavement run leaves behind, written the same way by `paver run` and by the
// studio's export: placements.csv, stones.csv, the mesh files of the chosen formats
// (io/mesh_formats.h: elements.ply/.obj/.stl/.glb, paved.3mf) and design.json, then report.json
// last so that it can carry the time the others took.
#include "elements/element_shape.h"
#include "io/mesh_formats.h"
#include "pipeline/pavement.h"
#include "pipeline/run_report.h"
#include "map/surface_map.h"

#include <nlohmann/json_fwd.hpp>

#include <atomic>
#include <filesystem>
#include <string>
#include <functional>
#include <vector>

namespace paver {

struct RunOutputOptions {
  const ShapeMesh* custom = nullptr;  // the design's custom shape, when an element uses it
  MeshFormats formats;                // which mesh files
  const std::atomic<bool>* stop = nullptr;  // when it becomes true, nothing more is written: Interrupted
};

// Every file name a run may leave in its output folder (the CLI's previews included).
std::vector<std::string> run_output_names();

// Every path the two functions below write in `folder`, for refuse_overwriting_inputs.
std::vector<std::filesystem::path> run_output_paths(const std::filesystem::path& folder, const MeshFormats& formats);

// The output guards, before any work: no output (the run's files of `formats` in `folder`, and the
// caller's `extra_outputs`) may replace one of `inputs`, `folder` must be a folder that can be
// written, and no file of the user's there may be replaced (io/output_set.h). InputError naming
// the file and the fix.
void check_run_outputs(const std::filesystem::path& folder, const MeshFormats& formats,
                       const std::vector<std::filesystem::path>& extra_outputs,
                       const std::vector<std::filesystem::path>& inputs);

// Creates `folder` if needed and writes the elements (the PLY coloured like the paper's figures:
// red = too close, through yellow, to green = loose; the glTF and 3MF with the surface `map`'s
// mesh) and the resolved design.
void write_run_files(const std::filesystem::path& folder, const SurfaceMap& map, const Pavement& pavement,
                     const RunOutputOptions& options = {});

// The export stage as run_pipeline and the studio's export run it, as one set (io/output_set.h):
// into a staging folder, write_run_files (timed as "export" in `timings`), then `extras` (the
// caller's own files, written into the folder it is given, adding their timings and any
// sections of their own to report.json), then write_run_report with every timing and
// report.html from it (with the extras' preview.png, if any); then the set is published into `folder` at once. Throws
// Interrupted, leaving `folder` as it was, when options.stop becomes true before publishing.
// Returns what the publish could not tidy (OutputSet::warnings), for the caller to pass on.
using ExtraOutputs =
    std::function<void(const std::filesystem::path& staging, StageTimings& timings, nlohmann::json& report_sections)>;
std::vector<std::string> write_run_outputs(const std::filesystem::path& folder, const RunInfo& info,
                                           const SurfaceMap& map, const Pavement& pavement, StageTimings& timings,
                                           const RunOutputOptions& options = {}, const ExtraOutputs& extras = {});

// Writes report.json (with `sections`, an object whose keys are added at its top level) and
// returns its content.
nlohmann::json write_run_report(const std::filesystem::path& folder, const RunInfo& info, const SurfaceMap& map,
                                const Pavement& pavement, const StageTimings& timings,
                                const nlohmann::json* sections = nullptr);

}  // namespace paver
