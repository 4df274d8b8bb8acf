// `paver run SURFACE [--design F] [--pattern P] [--spacing D] [--out DIR]`: the whole pipeline.
#include "backend_choice.h"
#include "commands.h"
#include "output_guard.h"
#include "run_outputs.h"
#include "preview_images.h"
#include "progress_bar.h"

#include "io/atomic_file.h"
#include "io/design_io.h"
#include "io/element_export.h"
#include "elements/element_proximity.h"
#include "core/input_error.h"
#include "mesh/mesh_loader.h"
#include "pipeline/pavement.h"
#include "report/run_report.h"

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
#include <utility>
#include <vector>

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
  bool no_optimize = false;
  bool no_postprocess = false;
  int threads = 0;
  // Section 5 parameters given on the command line (by name, as text), applied over the design's.
  std::vector<std::pair<const SolverParameter*, std::optional<std::string>>> solver_values;
  bool no_resolve = false;
  std::string backend = "auto";
  std::string device;
  bool png = false;
};

// A solver flag's value over the design's; a bad one blames the flag, not the design file.
void apply_solver_flag(SolverParams& solver, const SolverParameter& p, const std::string& text) {
  if (const auto problem = set_solver_parameter(solver, p, text))
    throw InputError("--" + std::string(p.flag) + " " + text + ": " + *problem);
}

double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
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
  for (const auto& [parameter, value] : args.solver_values)
    if (value) apply_solver_flag(design.solver, *parameter, *value);
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
  std::vector<fs::path> outputs = app::run_output_paths(out, false);
  if (args.png) outputs.insert(outputs.end(), {out / "preview.png", out / "param.png"});
  const std::vector<fs::path> inputs = {args.surface, args.design, design.elements.custom_shape};
  app::refuse_overwriting_inputs(inputs, outputs);

  t0 = Clock::now();
  const SurfaceMap map = [&] {
    try {
      return build_surface_map(std::move(loaded.mesh));
    } catch (const std::runtime_error& e) {
      throw std::runtime_error(args.surface + ": " + e.what());
    }
  }();
  timings.emplace_back("parameterize", ms_since(t0));

  PavementOptions options;
  options.observer = terminal_progress_bar(design.solver.iterations);
  options.optimize = !args.no_optimize;
  options.postprocess = !args.no_postprocess;
  options.threads = args.threads;
  options.resolve_collisions = !args.no_resolve;
  const app::BackendChoice backend = app::choose_backend(args.backend, args.device, args.threads);
  options.solver = backend.factory;
  Pavement pavement = make_pavement(map, design, options);
  finish_progress_bar();
  timings.insert(timings.end(), pavement.timings.begin(), pavement.timings.end());
  if (info.spacing_derived)
    std::printf("no spacing given: using D = %g, about 1000 points over this surface\n",
                pavement.design.pattern.spacing);

  t0 = Clock::now();
  app::write_run_files(out, pavement, {.custom = custom ? &*custom : nullptr});
  timings.emplace_back("export", ms_since(t0));
  if (args.png) {
    t0 = Clock::now();
    write_preview_images(out, map, pavement, custom ? &*custom : nullptr);
    timings.emplace_back("png", ms_since(t0));
  }
  const nlohmann::json report = app::write_run_report(out, info, map, pavement, timings);

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
  std::printf("optimize %s%s%s: %d iterations, %s (last max step %.3g); %d filled, %d eliminated at the boundary\n",
              backend.name.c_str(), backend.device.empty() ? "" : " on ", backend.device.c_str(), pavement.solve.iterations, std::string(stop_reason_name(pavement.solve.reason)).c_str(),
              pavement.solve.last_max_step, pavement.filled, pavement.eliminated);
  std::printf("elements %zu (%lld V, %lld E)\n", pavement.elements.size(), r["elements"]["vertex"].get<long long>(),
              r["elements"]["edge"].get<long long>());
  std::printf("quality           collisions  worst overlap  NN ratio min / p5 / median / p95   cv     crossings\n");
  for (const auto& [label, q] : {std::pair{"  initial", &pavement.before}, std::pair{"  paper's method", &pavement.paper},
                                 std::pair{"  final", &pavement.after}})
    std::printf("%-17s %10ld  %13.3f  %.3f / %.3f / %.3f / %.3f  %.3f  %ld\n", label, q->collisions,
                q->worst_overlap, q->neighbor_ratio.min, q->neighbor_ratio.p5, q->neighbor_ratio.median,
                q->neighbor_ratio.p95, q->neighbor_ratio.cv, q->boundary_crossings);
  std::printf("time    ");
  for (const auto& [stage, ms] : timings) std::printf(" %s %.1f ms,", stage.c_str(), ms);
  std::printf(" total %.1f ms\n", r["timings_ms"]["total"].get<double>());
  std::printf("wrote    %s/{placements.csv, elements.ply, elements.obj, design.json, report.json%s}\n",
              out.string().c_str(), args.png ? ", preview.png, param.png" : "");
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
  cmd->add_flag("--no-optimize", args->no_optimize, "Skip the section 5 optimizer (initial pavement only)");
  cmd->add_flag("--no-postprocess", args->no_postprocess, "Skip boundary filling and elimination (5.4)");
  cmd->add_option("--threads", args->threads, "Solver threads (0 = all cores)")->check(CLI::Range(0, 1024));
  cmd->add_option("--backend", args->backend, "Solver backend: cpu, vulkan, or auto (Vulkan on a GPU, else CPU)")
      ->check(CLI::IsMember({"cpu", "vulkan", "auto"}))
      ->capture_default_str();
  cmd->add_option("--device", args->device, "Vulkan device: a substring of its name (see `paver devices`)");
  cmd->add_flag("--png", args->png, "Also render preview.png (3D) and param.png (2D) offscreen with Vulkan");
  // Every section 5 parameter from the one table, named as in design.json's "solver" object.
  cmd->add_flag("--no-resolve", args->no_resolve, "Skip the contact-spring collision resolution (paper's method only)");
  args->solver_values.reserve(solver_parameters().size());
  for (const SolverParameter& p : solver_parameters()) {
    auto& slot = args->solver_values.emplace_back(&p, std::nullopt);
    std::string help = "solver." + std::string(p.name) + ": " + std::string(p.help) + " Default " + default_text(p);
    if (!p.unit.empty()) help += " (" + std::string(p.unit) + ")";
    CLI::Option* option = cmd->add_option("--" + std::string(p.flag), slot.second, help)->group("Solver (section 5)");
    if (std::holds_alternative<FilterBase SolverParams::*>(p.member))
      option->check(CLI::IsMember({"current", "initial"}))->type_name("TEXT");
    else
      option->type_name(std::holds_alternative<int SolverParams::*>(p.member) ? "INT" : "NUMBER");
  }
  return [args] { return run_run(*args); };
}

}  // namespace paver::cli
