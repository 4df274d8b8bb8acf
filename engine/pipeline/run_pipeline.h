#pragma once
// The whole pipeline in one call: design check -> surface -> map -> pattern -> spring system ->
// optimize -> elements -> post-process -> resolve collisions -> measure -> export. `paver run`,
// the studio's live runs, the benchmarks and the tests call it; each stage is also a function of
// its own (map_surface_file, make_pavement, write_run_outputs) for callers that redo only some.
//
// Inputs are checked before the expensive work: the design (validate_design, and its unit cell,
// operators, cell edges and overlaps: check_design_cell), its custom shape, and that no output
// would overwrite an input. Nothing is written unless `out` is given.
#include "design/design.h"
#include "elements/element_shape.h"
#include "io/mesh_formats.h"
#include "map/surface_map.h"
#include "pipeline/map_surface.h"
#include "pipeline/pavement.h"
#include "pipeline/run_report.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace paver {

struct PipelineResult;

struct PipelineRequest {
  // The surface: loaded and mapped from `surface_path`, unless `map` is given (the studio maps
  // once per surface and re-runs the rest on every design change; then `map_timings` says how
  // long that took, for the report).
  std::filesystem::path surface_path;
  // Only these named parts of the surface file (OBJ groups, `--region`), their borders its rims.
  std::vector<std::string> surface_region;
  std::shared_ptr<const SurfaceMap> map;
  StageTimings map_timings;

  Design design;
  std::string design_source = "defaults";  // names the design in errors and the report: its file, "defaults", "studio"
  std::filesystem::path design_path;       // the design file, if any: an input no output may overwrite
  // The command-line options that changed the design (e.g. "--gap 5"): a DesignError names them
  // with the file, since the fault may be theirs and not the file's.
  std::string design_overrides;
  // The design's custom shape, already read (the studio keeps it); read from
  // design.elements.custom_shape when an element uses it and this is empty.
  std::shared_ptr<const ShapeMesh> custom_shape;

  PavementOptions pavement;                // stages on/off, solver backend, observer, stop, on_pattern

  // Export: the run's files into `out` (placements.csv, stones.csv, the mesh files of `formats`,
  // design.json, report.json), published as one set (write_run_outputs). `extra_outputs` are files the caller
  // writes itself through `write_extras`, into the folder it is given (the set's staging folder),
  // with the names they will have in `out` (the CLI's PNG previews): they are checked against the
  // inputs too, and written before report.json so that its timings include them.
  std::optional<std::filesystem::path> out;
  MeshFormats formats;
  double max_output_bytes = 4e9;           // the mesh files are refused above this, before writing
  std::vector<std::filesystem::path> extra_outputs;
  // It may add sections of its own to report.json (keys of `report_sections`).
  std::function<void(const PipelineResult&, const std::filesystem::path& folder, StageTimings&,
                     nlohmann::json& report_sections)>
      write_extras;

  // Called once, just before the first output file or folder is created: until then a stopped run
  // has nothing to clean up (the CLI ends at once on Ctrl-C before it, since a factorization
  // cannot poll `stop`).
  std::function<void()> on_export;

  // The caller's own checks of the mapped surface, before the pattern (the CLI's ring size needs a
  // band): it may throw InputError, and nothing is written then.
  std::function<void(const SurfaceMap&)> check_map;

  PipelineProgress progress;               // loading and mapping progress
  PipelineWarning on_warning;              // the loader's repairs, as soon as they are known
};

struct PipelineResult {
  std::shared_ptr<const SurfaceMap> map;
  std::vector<std::string> warnings;          // the loader's repairs
  std::shared_ptr<const ShapeMesh> custom_shape;  // when an element uses it
  Pavement pavement;
  RunInfo info;
  StageTimings timings;                       // every stage, load to export
  PavementCounts counts;
  // A closed surface whose cut across its longest axis paved NOT OK is cut across x, y and z too
  // and the best kept (fewest verdict problems, then the highest fill): which, and why. Empty when
  // the first cut was kept without a try.
  std::string cut_axis_choice;
};

// Throws InputError for bad input (before the surface is read, except for the surface's own
// faults), std::runtime_error otherwise. When `pavement.stop` becomes true it throws Interrupted
// (core/interrupted.h) at the next stage boundary, having written nothing.
PipelineResult run_pipeline(PipelineRequest request);

}  // namespace paver
