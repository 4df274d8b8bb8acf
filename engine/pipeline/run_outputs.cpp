#include "pipeline/run_outputs.h"

#include "core/stopwatch.h"
#include "report/bill_of_stones.h"
#include "report/report_html.h"

#include "core/input_error.h"
#include "core/interrupted.h"
#include "io/output_set.h"

#include "io/output_guard.h"

#include "io/atomic_file.h"
#include "io/design_io.h"
#include "io/element_export.h"
#include "io/gltf_export.h"
#include "io/threemf_export.h"
#include "elements/element_proximity.h"
#include "report/pavement_quality.h"

#include <nlohmann/json.hpp>


namespace paver {

namespace fs = std::filesystem;

std::vector<fs::path> run_output_paths(const fs::path& folder, const MeshFormats& formats) {
  std::vector<fs::path> paths = {folder / "placements.csv", folder / "stones.csv", folder / "design.json",
                                 folder / "report.json", folder / "report.html"};
  for (const std::string& name : mesh_file_names(formats)) paths.push_back(folder / name);
  return paths;
}

void check_run_outputs(const fs::path& folder, const MeshFormats& formats, const std::vector<fs::path>& extra_outputs,
                       const std::vector<fs::path>& inputs) {
  std::vector<fs::path> outputs = run_output_paths(folder, formats);
  outputs.insert(outputs.end(), extra_outputs.begin(), extra_outputs.end());
  refuse_overwriting_inputs(inputs, outputs);
  check_output_folder(folder);  // a file there: "it is a file, not a folder"
  OutputSet::refuse_replacing_users_files(folder, outputs, run_output_names());
}

void write_run_files(const fs::path& folder, const SurfaceMap& map, const Pavement& pavement,
                     const RunOutputOptions& options) {
  make_output_folder(folder);
  ElementMeshOptions mesh_options;
  mesh_options.custom = options.custom;
  mesh_options.stop = options.stop;
  auto colours = contact_colours(pavement.elements, pavement.design.elements.gap);
  // The stones, then the beads (if any): the beads are exported with them, in their metal's colour.
  Elements with_beads;
  const Elements& exported = stones_and_beads(pavement, with_beads, &colours);
  mesh_options.colours = &colours;
  write_placements_csv(folder / "placements.csv", exported, options.stop);
  write_stones_csv(folder / "stones.csv", bill_of_stones(pavement.elements, pavement.design.units));
  const MeshFormats& formats = options.formats;
  if (formats.ply) write_elements_ply(folder / "elements.ply", exported, mesh_options);
  if (formats.obj) write_elements_obj(folder / "elements.obj", exported, mesh_options);
  // STL has no groups: the stones and the beads (metal, cast with the piece) are files of their own,
  // so that a shop can print or render one without the other (one file mixed them).
  if (formats.stl) {
    write_elements_stl(folder / "elements.stl", pavement.elements, mesh_options);
    if (pavement.beads.size() > 0) write_elements_stl(folder / "beads.stl", pavement.beads, mesh_options);
  }
  if (formats.glb)
    write_pavement_glb(folder / "elements.glb", {.mesh = &map.mesh, .normals = &map.normals}, exported,
                       pavement.design.units, mesh_options);
  if (formats.threemf)
    write_pavement_3mf(folder / "paved.3mf", &map.mesh, exported, pavement.design.units, mesh_options);
  save_design(folder / "design.json", pavement.design);
}

std::vector<std::string> run_output_names() {
  std::vector<std::string> names = {"placements.csv", "stones.csv", "design.json", "report.json", "report.html", "preview.png",
                                    "param.png",      "cut.stl",     "cut.3mf",     "cut.png",     "beads.stl"};
  for (std::string& name : all_mesh_file_names()) names.push_back(std::move(name));
  return names;
}

std::vector<std::string> write_run_outputs(const fs::path& folder, const RunInfo& info, const SurfaceMap& map,
                                           const Pavement& pavement, StageTimings& timings,
                                           const RunOutputOptions& options, const ExtraOutputs& extras) {
  const auto check_stop = [&] {
    if (options.stop && options.stop->load()) throw Interrupted();
  };
  check_stop();
  OutputSet set(folder, run_output_names());
  try {
    const Stopwatch watch;
    write_run_files(set.staging(), map, pavement, options);
    timings.emplace_back("export", watch.milliseconds());
    check_stop();
    nlohmann::json sections = nlohmann::json::object();
    if (extras) extras(set.staging(), timings, sections);
    check_stop();
    const nlohmann::json report = write_run_report(set.staging(), info, map, pavement, timings, &sections);
    write_report_html(set.staging(), report);
  } catch (const InputError& e) {
    // Nothing is published, so the folder is as it was.
    throw InputError(set.with_final_names(e.what()) + "; " + folder.string() + " is left as it was");
  }
  check_stop();
  set.publish("report.json");
  return set.warnings();
}

nlohmann::json write_run_report(const fs::path& folder, const RunInfo& info, const SurfaceMap& map,
                                const Pavement& pavement, const StageTimings& timings, const nlohmann::json* sections) {
  nlohmann::json report = make_run_report(info, map, pavement, timings);
  if (sections)
    for (const auto& [key, value] : sections->items()) report[key] = value;
  write_text_atomically(folder / "report.json", report.dump(2) + "\n");
  return report;
}

}  // namespace paver
