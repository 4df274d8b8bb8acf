// `paver run SURFACE [--design F] [--pattern P] [--spacing D] [--out DIR]`: the whole pipeline.
#include "commands.h"
#include "output_guard.h"

#include "paver/atomic_file.h"
#include "paver/design_io.h"
#include "paver/element_export.h"
#include "paver/input_error.h"
#include "paver/mesh_loader.h"
#include "paver/pavement.h"
#include "paver/run_report.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>

namespace paver::cli {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct RunArgs {
  std::string surface;
  std::string design;
  std::string pattern;
  std::optional<double> spacing;
  std::string out = "out";
};

double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

bool uses_custom_shape(const ElementsDesign& e) {
  if (e.vertex.enabled && e.vertex.shape == ShapeKind::Custom) return true;
  return std::any_of(e.edge.begin(), e.edge.end(), [](const auto& s) { return s.shape == ShapeKind::Custom; });
}

int run_run(const RunArgs& args) {
  StageTimings timings;
  auto t0 = Clock::now();
  LoadedSurface loaded = load_surface(args.surface);
  for (const auto& w : loaded.warnings) std::cerr << "paver: warning: " << w << "\n";
  timings.emplace_back("load", ms_since(t0));

  Design design;
  RunInfo info{args.surface, args.design.empty() ? "defaults" : args.design, false};
  if (!args.design.empty()) design = load_design(args.design);
  if (!args.pattern.empty()) {
    const auto t = tessellation_from_name(args.pattern);
    if (!t) throw InputError("--pattern " + args.pattern + ": use tri, grid or hex");
    design.pattern.tessellation = *t;
  }
  if (args.spacing) {
    // Checked here so that a bad flag is not reported as a fault of the design file.
    if (!(std::isfinite(*args.spacing) && *args.spacing >= 0)) {
      std::ostringstream given;
      given << *args.spacing;
      throw InputError("--spacing " + given.str() + ": must be finite and >= 0 (0 = derive from the surface)");
    }
    design.pattern.spacing = *args.spacing;
  }
  validate_design(design, args.design.empty() ? "command line" : args.design);
  info.spacing_derived = design.pattern.spacing <= 0;

  std::optional<ShapeMesh> custom;
  if (uses_custom_shape(design.elements)) custom = load_custom_shape(design.elements.custom_shape);

  // Refuse before any work is written if an output would replace an input.
  const fs::path out = args.out;
  const std::vector<fs::path> outputs = {out / "placements.csv", out / "elements.ply", out / "elements.obj",
                                         out / "design.json", out / "report.json"};
  const std::vector<fs::path> inputs = {args.surface, args.design, design.elements.custom_shape};
  refuse_overwriting_inputs(inputs, outputs);

  t0 = Clock::now();
  const SurfaceMap map = build_surface_map(std::move(loaded.mesh));
  timings.emplace_back("parameterize", ms_since(t0));
  if (!map.parameterization.quality.bijective())
    throw std::runtime_error("the parameterization is not bijective; please report this surface");

  Pavement pavement = make_pavement(map, design);
  timings.insert(timings.end(), pavement.timings.begin(), pavement.timings.end());
  if (info.spacing_derived)
    std::printf("no spacing given: using D = %g, about 1000 points over this surface\n",
                pavement.design.pattern.spacing);

  t0 = Clock::now();
  make_output_folder(out);
  ElementMeshOptions mesh_options;
  if (custom) mesh_options.custom = &*custom;
  write_placements_csv(out / "placements.csv", pavement.elements);
  write_elements_ply(out / "elements.ply", pavement.elements, mesh_options);
  write_elements_obj(out / "elements.obj", pavement.elements, mesh_options);
  save_design(out / "design.json", pavement.design);
  timings.emplace_back("export", ms_since(t0));
  const nlohmann::json report = make_run_report(info, map, pavement, timings);
  write_text_atomically(out / "report.json", report.dump(2) + "\n");

  const auto& q = map.parameterization.quality;
  const auto& pr = map.parameterization.report;
  const auto& r = report;
  std::printf("surface  %s: %d vertices, %d faces, area %.6g\n", args.surface.c_str(), map.mesh.vertex_count(),
              map.mesh.face_count(), surface_area(map.mesh));
  std::printf("map      ARAP from %s, %d iterations: %d flips, %d boundary overlaps, s1/s2 mean %.3f max %.3f\n",
              pr.start_used == ArapStart::Lscm ? "LSCM" : "Tutte", pr.iterations, q.flipped_triangles,
              q.boundary_intersections, q.stretch_mean, q.stretch_max);
  std::printf("pattern  %s, D = %g: %d points, %lld edges (+%lld virtual), %lld edges cross the boundary\n",
              std::string(tessellation_name(pavement.design.pattern.tessellation)).c_str(),
              pavement.design.pattern.spacing, pavement.pattern.point_count(),
              r["pattern"]["edges"].get<long long>(), r["pattern"]["virtual_edges"].get<long long>(),
              r["pattern"]["boundary_crossing_edges"].get<long long>());
  std::printf("elements %zu (%lld V, %lld E)\n", pavement.elements.size(), r["elements"]["vertex"].get<long long>(),
              r["elements"]["edge"].get<long long>());
  std::printf("time    ");
  for (const auto& [stage, ms] : timings) std::printf(" %s %.1f ms,", stage.c_str(), ms);
  std::printf(" total %.1f ms\n", r["timings_ms"]["total"].get<double>());
  std::printf("wrote    %s/{placements.csv, elements.ply, elements.obj, design.json, report.json}\n",
              out.string().c_str());
  return 0;
}

}  // namespace

std::function<int()> add_run_command(CLI::App& app) {
  auto args = std::make_shared<RunArgs>();
  CLI::App* cmd = app.add_subcommand("run", "Pave a surface: map, pattern, elements, export and report");
  cmd->add_option("SURFACE", args->surface, "Open surface: OBJ, OFF, PLY or STL")->required();
  cmd->add_option("--design", args->design, "design.json (flags below override it)");
  cmd->add_option("--pattern", args->pattern, "Tessellation: tri, grid or hex");
  cmd->add_option("--spacing", args->spacing, "Edge length D in surface units (default: from the surface size)");
  cmd->add_option("--out", args->out, "Output folder")->capture_default_str();
  return [args] { return run_run(*args); };
}

}  // namespace paver::cli
