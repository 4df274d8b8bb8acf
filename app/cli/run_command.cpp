// `paver run SURFACE [--design F] [--pattern P] [--spacing D] [--out DIR]`: the whole pipeline.
#include "available_memory.h"
#include "backend_choice.h"
#include "command_line.h"
#include "commands.h"
#include "preview_images.h"
#include "interrupt.h"
#include "progress.h"

#include "core/input_error.h"
#include "core/number_text.h"
#include "core/printable.h"
#include "core/stopwatch.h"
#include "io/coordinate_precision.h"
#include "io/design_io.h"
#include "pipeline/run_pipeline.h"
#include "pattern/adaptive_pattern.h"
#include "report/bill_of_stones.h"
#include "io/element_export.h"
#include "io/stl_unit_warning.h"
#ifdef PAVER_WITH_CGAL
#include "cut/cut_outputs.h"
#endif
#include "report/verdict.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace paver::cli {
namespace {

namespace fs = std::filesystem;

struct RunArgs {
  std::string surface;
  std::string design;
  std::string pattern;
  std::string topology;
  std::string rim_rows;
  std::string cut;  // empty: the design's
  std::string align;  // empty: the design's (placement.align, default none)
  bool fit_offset = false;  // else the design's (placement.fit_offset, default false)
  std::optional<double> spacing;
  std::optional<double> gap;
  std::optional<double> margin;
  bool beads = false;
  std::optional<double> stone;
  std::string units;
  std::string out = "out";
  bool no_optimize = false;
  bool no_postprocess = false;
  int threads = 0;
  // Section 5 parameters given on the command line (by name, as text), applied over the design's.
  std::vector<std::pair<const SolverParameter*, std::optional<std::string>>> solver_values;
  bool no_resolve = false;
  bool no_refill = false;
  std::string backend = "auto";
  std::string device;
  bool png = false;
  double max_output_gb = 4;
  std::string formats = "ply,obj,glb,3mf";
  bool subtract = false;
  std::optional<double> thickness;
  std::string cutter = "seat";
  bool quiet = false;
};

// A solver flag's value over the design's; a bad one blames the flag, not the design file.
void apply_solver_flag(SolverParams& solver, const SolverParameter& p, const std::string& text) {
  if (const auto problem = set_solver_parameter(solver, p, text))
    throw InputError("--" + std::string(p.flag) + " " + text + ": " + *problem);
}

// `paver run` wrote its files but the verdict is NOT OK (README, "Exit codes").
constexpr int kExitVerdictNotOk = 3;

// A numeric flag that must be finite and >= 0: its value, or an InputError naming the flag.
double finite_non_negative(const char* flag, double value, const char* meaning) {
  if (std::isfinite(value) && value >= 0) return value;
  throw InputError(std::string(flag) + " " + number_text(value) + ": must be finite and >= 0 (" + meaning + ")");
}

// A numeric flag that must be finite and > 0 (a size): its value, or an InputError naming the flag.
double finite_positive(const char* flag, double value, const char* meaning) {
  if (std::isfinite(value) && value > 0) return value;
  throw InputError(std::string(flag) + " " + number_text(value) + ": must be finite and > 0 (" + meaning + ")");
}


int run_run(const RunArgs& args) {
  nothing_written_yet();
  PipelineRequest request;
  request.surface_path = args.surface;
  request.design_source = args.design.empty() ? "defaults" : args.design;
  request.design_path = args.design;
  const auto warn = [](const std::string& w) { std::cerr << "paver: warning: " << printable(w) << "\n"; };
  request.on_warning = warn;
  Design& design = request.design;
  if (!args.design.empty()) {
    std::vector<std::string> notes;
    design = load_design(args.design, &notes);
    for (const std::string& note : notes) request.on_warning(note);
  }
  if (!args.align.empty()) {
    const std::optional<AlignAxis> axis = align_axis_from_name(args.align);
    if (!axis) throw InputError("--align " + printable(args.align) + ": use x, y, z or none");
    design.placement.align = *axis;
  }
  if (args.fit_offset) design.placement.fit_offset = true;
  if (!args.cut.empty()) {  // else the design's (placement.cut_axis, default auto)
    const std::optional<CutAxis> cut_axis = cut_axis_from_name(args.cut);
    if (!cut_axis) throw InputError("--cut " + printable(args.cut) + ": use auto, x, y or z");
    design.placement.cut_axis = *cut_axis;
  }
  if (!args.pattern.empty()) {
    const auto t = tessellation_from_name(args.pattern);
    if (!t) throw InputError("--pattern " + args.pattern + ": use tri, grid or hex");
    design.pattern.tessellation = *t;
  }
  if (!args.topology.empty()) {
    const auto t = topology_from_name(args.topology);
    if (!t) throw InputError("--topology " + args.topology + ": use auto, lattice or adaptive");
    design.pattern.topology = *t;
  }
  for (const auto& [parameter, value] : args.solver_values)
    if (value) apply_solver_flag(design.solver, *parameter, *value);
  if (!args.units.empty()) {
    const auto u = units_from_name(args.units);
    if (!u) throw InputError("--units " + printable(args.units) + ": use mm, cm, m or in (the unit of the surface's coordinates)");
    design.units = *u;
  }
  // Checked here so that a bad flag is not reported as a fault of the design file.
  if (args.spacing)
    design.pattern.spacing = finite_non_negative("--spacing", *args.spacing, "0 = derive from the surface");
  if (args.gap)
    design.elements.gap = finite_non_negative("--gap", *args.gap, "free space between elements, surface units");
  if (!args.rim_rows.empty()) {
    const auto r = rim_rows_from_name(args.rim_rows);
    if (!r) throw InputError("--rim-rows " + printable(args.rim_rows) + ": use none, holes or all");
    design.elements.rim_rows = *r;
  }
  if (args.margin)
    design.elements.margin =
        finite_non_negative("--margin", *args.margin, "free band along the surface's boundary, surface units");
  if (args.beads) design.elements.beads.enabled = true;
  if (args.stone) {
    if (args.spacing) throw InputError("--stone and --spacing both set the spacing (D = stone + gap): give one of them");
    const double stone = finite_positive("--stone", *args.stone, "the stone's diameter, surface units");
    set_stone_size(design, stone);
    // Pavé is a close packing: with no pattern asked for anywhere, stones go on a triangle lattice.
    if (args.pattern.empty() && args.design.empty()) design.pattern.tessellation = Tessellation::Triangle;
  }
  // The options that shape the pattern and its elements, named with the file in a design error.
  std::string overrides;
  const auto given = [&](const std::string& flag, const std::string& value) {
    overrides += (overrides.empty() ? "" : " ") + flag + (value.empty() ? "" : " " + printable(value));
  };
  if (!args.pattern.empty()) given("--pattern", args.pattern);
  if (!args.topology.empty()) given("--topology", args.topology);
  if (!args.align.empty()) given("--align", args.align);
  if (args.fit_offset) given("--fit-offset", "");
  if (args.spacing) given("--spacing", number_text(*args.spacing));
  if (args.stone) given("--stone", number_text(*args.stone));
  if (args.gap) given("--gap", number_text(*args.gap));
  if (args.margin) given("--margin", number_text(*args.margin));
  if (args.beads) given("--beads", "");
  request.design_overrides = overrides;
  // Element edits name the elements of the layout they were made on: a flag that lays the pattern
  // out anew sends them to other elements, said before the run rather than found in its result.
  if (!design.edits.empty()) {
    std::string relaid;
    for (const auto& [flag, given_flag] : {std::pair{"--pattern", !args.pattern.empty()},
                                           {"--topology", !args.topology.empty()},
                                           {"--spacing", args.spacing.has_value()},
                                           {"--align", !args.align.empty()}})
      if (given_flag) relaid += (relaid.empty() ? "" : ", ") + std::string(flag);
    if (!relaid.empty())
      warn(relaid + " lays the pattern out anew under this design's element edits, which name the elements of the "
           "layout they were made on: they may land on other elements (edit again after the change)");
  }
  // A design.json written by a run with --align holds the turn in rotation_deg already.
  if (!args.align.empty() && design.placement.align != AlignAxis::None && design.placement.rotation_deg != 0 &&
      !args.design.empty()) {
    char degrees[32];
    std::snprintf(degrees, sizeof degrees, "%.1f", design.placement.rotation_deg);
    warn("--align " + printable(args.align) + ": " + args.design + " turns the pattern by placement.rotation_deg " +
         degrees + " degrees on top of the alignment; a design.json written by a run with --align holds that run's "
         "turn there already, so give --align only to a design without it");
  }
  // What the flags and the file give together (c + m >= 0), named after where it came from.
  validate_design(design, args.design.empty() ? "command line" : args.design);

  Progress progress(args.quiet, stderr_is_terminal());
  request.progress = progress.mapping();
  PavementOptions& options = request.pavement;
  options.on_stage = [&](const std::string& stage) { progress.stage(stage); };
  options.observer = progress.solver(design.solver.iterations);
  options.optimize = !args.no_optimize;
  options.postprocess = !args.no_postprocess;
  options.threads = args.threads;
  options.resolve_collisions = !args.no_resolve;
  options.refill = !args.no_refill;
  options.stop = &interrupt_requested();
  const app::BackendChoice backend = app::choose_backend(args.backend, args.device, args.threads);
  options.solver = backend.factory;

  const fs::path out = args.out;
  request.out = out;
  request.max_output_bytes = args.max_output_gb * 1e9;
  try {
    request.formats = parse_mesh_formats(args.formats);
  } catch (const InputError& e) {
    throw InputError("--formats " + printable(args.formats) + ": " + e.what());
  }
  request.on_export = [&] {
    writing_starts();
    progress.stage("export");
  };
  std::optional<PreviewImages> previews;
  // The subtractive solid: its flags are checked now, the cut made with the other files.
  nlohmann::json cut_summary;
  std::function<void(const PipelineResult&, const fs::path&, StageTimings&, nlohmann::json&)> write_cut;
  if (args.cutter != "seat" && args.cutter != "element")
    throw InputError("--cutter " + printable(args.cutter) + ": use seat (girdle, seat cone, hole through) or element");
  if (!args.subtract && args.thickness) throw InputError("--thickness is the metal's for --subtract: add --subtract");
  if (args.subtract) {
    if (!args.thickness) throw InputError("--subtract needs --thickness T: how thick the metal is, surface units");
    // Checked in every build, so that a bad value says so before "this build has no CGAL".
    [[maybe_unused]] const double thickness =
        finite_positive("--thickness", *args.thickness, "the metal's thickness, surface units");
#ifdef PAVER_WITH_CGAL
    request.extra_outputs.insert(request.extra_outputs.end(), {out / "cut.stl", out / "cut.3mf"});
    if (args.png) request.extra_outputs.push_back(out / "cut.png");
    const CutterKind cutter = args.cutter == "seat" ? CutterKind::Seat : CutterKind::Element;
    write_cut = [&, thickness, cutter](const PipelineResult& r, const fs::path& folder, StageTimings& timings,
                                       nlohmann::json& sections) {
      const CutOptions cut_options{.cutter = cutter, .thickness = thickness, .custom = r.custom_shape.get(),
                                   .stop = &interrupt_requested(), .beads = &r.pavement.beads};
      // Before the cut, which cannot report its progress: refused when it would not fit in memory,
      // and its size said (docs/benchmarks.md: it grows faster than the count).
      refuse_cut_beyond_memory(r.pavement.elements, cut_options, app::available_memory_bytes());
      progress.stage("cut: " + std::to_string(r.pavement.elements.size()) +
                     " cutters in one boolean, which reports no progress (3,933 took 105 s and 7,033 took 422 s "
                     "on 2 cores)");
      const Stopwatch watch;
      const CutSolid cut = cut_pavement(*r.map, r.pavement.elements, cut_options);
      write_cut_files(folder, cut, r.pavement.elements, r.pavement.design.units, r.custom_shape.get(),
                      &interrupt_requested());
      if (previews) previews->write_solid(folder / "cut.png", cut.mesh, r.map->mesh);
      timings.emplace_back("cut", watch.milliseconds());
      cut_summary = sections["cut"] = cut_json(cut, cutter, thickness, r.pavement.design.units);
      const std::string stand_out = stones_stand_out_warning(cut, thickness, r.pavement.design.units);
      if (!stand_out.empty()) warn(stand_out);  // the request has been handed to the pipeline
      const std::string rounded = coordinate_rounding_warning(r.pavement.elements, "cut.stl", "cut.3mf");
      if (!rounded.empty()) warn(rounded);
    };
#else
    throw InputError("--subtract: this paver was built without CGAL (-DPAVER_WITH_CGAL=OFF); rebuild with it");
#endif
  }
  if (args.png) {
    previews = PreviewImages::open();  // no device: refused now, before any work
    request.extra_outputs.insert(request.extra_outputs.end(), {out / "preview.png", out / "param.png"});
  }
  request.write_extras = [&](const PipelineResult& r, const fs::path& folder, StageTimings& timings,
                             nlohmann::json& sections) {
    if (write_cut) write_cut(r, folder, timings, sections);
    if (previews) {
      const Stopwatch watch;
      previews->write(folder, *r.map, r.pavement, r.custom_shape.get());
      timings.emplace_back("png", watch.milliseconds());
    }
  };
  std::vector<std::string> stl_files;
  if (request.formats.stl) stl_files.push_back("elements.stl");
  if (args.subtract) stl_files.push_back("cut.stl");
  const std::string stl_units = stl_unit_warning(request.design.units, stl_files);
  if (!stl_units.empty()) warn(stl_units);
  const MeshFormats request_formats = request.formats;
  const PipelineResult result = run_pipeline(std::move(request));
  progress.finish();
  const SurfaceMap& map = *result.map;
  const Pavement& pavement = result.pavement;
  const PavementCounts& counts = result.counts;

  const Verdict verdict = judge_pavement(pavement.after);
  std::printf("verdict  %s\n", verdict.ok ? "ok: no contact violations, no boundary crossings, pattern intact"
                                          : "NOT OK:");
  for (const std::string& problem : verdict.problems) std::printf("         - %s\n", problem.c_str());
  // A lattice that tore or left bare patches is what the adaptive topology is for.
  const bool lattice_failed = pattern_is_torn(pavement.after) || has_bare_patches(pavement.after);
  // Not when auto tried the adaptive pattern already and it did no better (topology_choice says so).
  if (lattice_failed && pavement.design.pattern.topology == Topology::Lattice && pavement.topology_choice.empty() &&
      adaptive_pattern_unsupported(pavement.design).empty())
    std::printf("         hint: the map distorts the lattice here; --topology adaptive grows the pattern on the "
                "surface instead (docs/topology.md)\n");
  if (result.info.spacing_derived)
    std::printf("no spacing given: using D = %g, about 1000 points over this surface\n",
                pavement.design.pattern.spacing);
  const auto& q = map.parameterization.quality;
  const auto& pr = map.parameterization.report;
  const int holes = map.mesh.hole_count();
  const std::string shape = is_atlas(map) ? "a closed surface, cut into " + std::to_string(chart_count(map)) +
                                                  " charts (" + std::to_string(map.mesh.boundary_loops.size()) +
                                                  " seam loops, each chart's side counted)"
                            : holes == 0 ? "a disk"
                            : holes == 1 ? "a band or a disk with a hole (2 boundary loops)"
                                         : std::to_string(holes) + " holes (" + std::to_string(holes + 1) + " boundary loops)";
  std::printf("surface  %s: %d vertices, %d faces, area %.6g, %s\n", printable(args.surface).c_str(),
              is_atlas(map) ? map.closed_surface_vertices : map.mesh.vertex_count(),
              is_atlas(map) ? map.closed_surface_faces : map.mesh.face_count(), surface_area(map.mesh), shape.c_str());
  std::printf("map      %s, %d iterations: %d flips, %d boundary overlaps, s1/s2 mean %.3f max %.3f\n",
              map_method_name(pr).c_str(), pr.iterations, q.flipped_triangles,
              q.boundary_intersections, q.stretch_mean, q.stretch_max);
  std::printf("pattern  %s %s, D = %g: %d points, %ld edges (+%ld virtual), %ld edges cross the boundary",
              std::string(tessellation_name(pavement.design.pattern.tessellation)).c_str(),
              std::string(topology_name(pavement.design.pattern.topology)).c_str(),
              pavement.design.pattern.spacing, pavement.pattern.point_count(), counts.pattern_edges,
              counts.virtual_edges, counts.boundary_crossing_edges);
  if (pavement.design.pattern.topology == Topology::Adaptive)
    std::printf("; %zu point defects, relaxed in %d iterations and packed in %d (%d jammed removed), %.0f ms",
                pavement.pattern.defects.size(), pavement.relaxation.iterations,
                pavement.relaxation.packing_iterations, pavement.relaxation.jammed, pavement.relaxation.milliseconds);
  if (const DefectHealingReport& healed = pavement.relaxation.healing; healed.tries > 0)
    std::printf("; interior defects healed %d -> %d (%d of %d shaken patches rearranged, %.0f ms)", healed.defects_before,
                healed.defects_after, healed.moved, healed.tries, healed.milliseconds);
  std::printf("\n");
  if (!pavement.topology_choice.empty()) std::printf("topology %s\n", pavement.topology_choice.c_str());
  if (!result.cut_axis_choice.empty()) std::printf("cut axis %s\n", result.cut_axis_choice.c_str());
  if (const auto& a = pavement.row_alignment) {
    char total[64] = "";
    if (pavement.design.placement.rotation_deg != a->rotation_deg)
      std::snprintf(total, sizeof total, ", %.1f with placement.rotation_deg", pavement.design.placement.rotation_deg);
    std::printf("align    rows along %s: the pattern turned %.1f degrees%s; the axis meets the surface at %.0f "
                "degrees on average and its direction on the map varies by %.1f degrees\n",
                std::string(align_axis_name(a->axis)).c_str(), std::abs(a->rotation_deg) < 0.05 ? 0.0 : a->rotation_deg, total, a->axis_to_surface_deg,
                a->spread_deg);
  }
  if (const auto& f = pavement.offset_fit) {
    const OffsetCandidate& c = f->chosen;
    std::printf("offset   fitted: the lattice shifted (%.4g, %.4g) cells to (%.4g, %.4g): ", c.shift_in_cells.x,
                c.shift_in_cells.y, c.offset.x, c.offset.y);
    if (c.kept >= 0)
      std::printf("%ld elements kept against %ld at the design's offset (the best of %zu shifts paved in full, out of %d "
                  "laid out)\n",
                  c.kept, f->at_design.kept, f->finalists.size(), f->tries);
    else
      std::printf("%zu elements laid out against %zu at the design's offset (the best of %d shifts; a pattern this "
                  "large is not paved at each)\n",
                  c.laid_out, f->at_design.laid_out, f->tries);
  }
  if (is_band(map)) {
    if (pavement.band_closure)
      std::printf("band     seamless (period %.6g, map s1/s2 mean %.3f): %s\n", map.seamless->period,
                  map.seamless->parameterization.quality.stretch_mean, describe_band_closure(*pavement.band_closure).c_str());
    else
      std::printf("band     paved as an annulus: %s\n", band_annulus_reason(map, pavement).c_str());
  }
  // The backend that ran the main solve: auto takes the CPU for a small system, and the adaptive
  // pattern's optimizer runs on the CPU whatever was asked.
  const std::string ran = pavement.solve.backend.empty() ? backend.name : pavement.solve.backend;
  const bool on_device = ran == "vulkan" && !backend.device.empty();
  std::printf("optimize %s%s%s: %d iterations, %s (last max step %.3g); %d filled, %d eliminated at the boundary, "
              "%d removed still colliding\n",
              ran.c_str(), on_device ? " on " : "", on_device ? backend.device.c_str() : "", pavement.solve.iterations, std::string(stop_reason_name(pavement.solve.reason)).c_str(),
              pavement.solve.last_max_step, pavement.filled, pavement.eliminated, pavement.resolution.removed);
  if (!pavement.coarse_start.level_points.empty()) {
    std::printf("         multilevel start:");
    for (int points : pavement.coarse_start.level_points) std::printf(" %d", points);
    std::printf(" points, %d particles found no room\n", pavement.coarse_start.retired);
  }
  if (pavement.resolution.retired > 0)
    std::printf("         %d vacancies where contact springs stalled\n", pavement.resolution.retired);
  if (const ElementEdits& edits = pavement.design.edits; !edits.empty()) {
    std::printf("edits    %zu moved (%d pinned), %zu added, %zu deleted", edits.moved.size(), edits.pinned_count(), edits.added.size(),
                edits.deleted.size() - std::size_t(pavement.deletions_missed));
    if (pavement.deletions_missed > 0)
      std::printf("; %d deletions found no element (a refilled one the edits moved away)", pavement.deletions_missed);
    std::printf("\n");
  }
  std::printf("elements %zu (%ld V, %ld E), %d of them added into bare regions", pavement.elements.size(),
              counts.vertex_elements, counts.edge_elements, pavement.refill.added);
  if (is_atlas(map)) std::printf(" (%d across the seams)", pavement.refill.on_seams);
  std::printf("\n");
  if (pavement.design.elements.rim_rows != RimRows::None)
    std::printf("rim rows %s: %d of %zu rims, %d elements along them; %d pattern elements made way\n",
                std::string(rim_rows_name(pavement.design.elements.rim_rows)).c_str(), pavement.rim_rows.loops,
                rim_row_loops(map, pavement.design.elements.rim_rows).size(), pavement.rim_rows.placed,
                pavement.rim_rows.made_way);
  const BillOfStones bill = bill_of_stones(pavement.elements, pavement.design.units);
  for (const StoneRow& row : bill.rows) {
    std::printf("stones   %ld %s of %.2f mm", row.count, std::string(shape_name(row.shape)).c_str(), row.diameter_mm);
    // Three significant digits each, so that count x each gives the total to its last digit.
    if (row.carat_each) std::printf(", %.3g ct each, %s ct", *row.carat_each, carat_total_text(row.carat_total).c_str());
    std::printf("\n");
  }
  // Totals as stones.csv writes them (12.9195 there printed 12.919 here).
  if (bill.weighed())
    std::printf("stones   total %ld, %s ct (stones.csv)\n", bill.count, carat_total_text(bill.carat_total).c_str());
  if (pavement.design.elements.beads.enabled) {
    const nlohmann::json beads = beads_json(pavement);
    std::printf("beads    %zu shared prongs of %.2f to %.2f mm, between every three stones in contact%s\n",
                beads["count"].get<std::size_t>(), beads["diameter_mm_min"].get<double>(),
                beads["diameter_mm_max"].get<double>(),
                pavement.beads.size() == 0 ? " (none: no three stones touch; beads need a tri pattern)" : "");
  }
  if (!cut_summary.is_null()) {
    const std::string unit(units_name(pavement.design.units));
    std::printf("cut      %s cutters, metal %g %s thick: %.4g mm3 of %.4g mm3 left (%.4g removed), closed and manifold; "
                "%s triangles\n",
                cut_summary["cutter"].get<std::string>().c_str(), cut_summary["thickness"].get<double>(), unit.c_str(),
                cut_summary["volume_mm3"].get<double>(), cut_summary["shell_volume_mm3"].get<double>(),
                cut_summary["removed_mm3"].get<double>(), std::to_string(cut_summary["triangles"].get<std::size_t>()).c_str());
    std::printf("metal   ");
    for (const auto& row : cut_summary["metal"])
      std::printf(" %s %.2f g;", row["alloy"].get<std::string>().c_str(), row["grams"].get<double>());
    std::printf("\n");
  }
  // Lengths in the surface's unit; NN over the diameter (param.png colours NN over diameter + gap).
  const std::string unit(units_name(pavement.design.units));
  std::printf("quality (gap %g %s; clearance in %s; NN = nearest-neighbour distance / diameter)\n",
              pavement.design.elements.gap, unit.c_str(), unit.c_str());
  std::printf("                  violations  min clearance  NN min / p5 / median / p95         cv     crossings  fill\n");
  for (const auto& [label, q] : {std::pair{"  initial", &pavement.before}, std::pair{"  paper's method", &pavement.paper},
                                 std::pair{"  final", &pavement.after}})
    std::printf("%-17s %10ld  %13.4g  %.4f / %.4f / %.4f / %.4f  %.3f  %-9ld  %.3f\n", label, q->contact_violations,
                q->min_clearance, q->neighbor_ratio.min, q->neighbor_ratio.p5, q->neighbor_ratio.median,
                q->neighbor_ratio.p95, q->neighbor_ratio.cv, q->boundary_crossings, q->fill);
  const PavementQuality& final_quality = pavement.after;
  std::printf("fill by kind: V %.3f", final_quality.vertex_fill);
  if (counts.edge_elements > 0) std::printf(", E %.3f", final_quality.edge_fill);
  if (final_quality.interior_vertex_elements > 0)
    std::printf("; regular valence: %.1f%% of %ld interior V-elements", 100 * final_quality.regular_valence_share,
                final_quality.interior_vertex_elements);
  std::printf("\n");
  std::printf("time    ");
  double total = 0;
  for (const auto& [stage, ms] : result.timings) std::printf(" %s %.1f ms,", stage.c_str(), ms), total += ms;
  std::printf(" total %.1f ms\n", total);
  std::string written = "placements.csv, stones.csv";
  for (const std::string& name : mesh_file_names(request_formats)) written += ", " + name;
  written += ", design.json, report.json, report.html";
  if (!cut_summary.is_null()) written += args.png ? ", cut.stl, cut.3mf, cut.png" : ", cut.stl, cut.3mf";
  if (args.png) written += ", preview.png, param.png";
  std::printf("wrote    %s/{%s}\n", printable(out.string()).c_str(), written.c_str());
  // The files are written either way (to look at); a script learns from the code that they failed.
  return verdict.ok ? 0 : kExitVerdictNotOk;
}

}  // namespace

std::function<int()> add_run_command(CLI::App& app) {
  auto args = std::make_shared<RunArgs>();
  CLI::App* cmd = app.add_subcommand("run", "Pave a surface: map, pattern, elements, export and report");
  cmd->add_option("SURFACE", args->surface, "Surface: OBJ, OFF, PLY or STL (open, or closed without handles)")->required();
  cmd->add_option("--design", args->design, "design.json (flags below override it)");
  cmd->add_option("--pattern", args->pattern, "Tessellation: tri, grid or hex");
  cmd->add_option("--topology", args->topology,
                  "auto (default: the lattice, or the adaptive pattern where the lattice tears or leaves bare patches), "
                  "lattice (the paper's) or adaptive: particles grown on the surface with point defects, for maps "
                  "that distort a lattice (tri and hex; docs/topology.md)");
  cmd->add_option("--align", args->align,
                  "Rows along a world axis: x, y, z, or none (the map's own orientation; the default): the pattern "
                  "is turned so that its rows follow the axis as it lies on the surface (placement.align)");
  cmd->add_flag("--fit-offset", args->fit_offset,
                "Shift the lattice within one cell to where the most elements fit (placement.fit_offset): with "
                "rows along an axis, whole rows meet a window's edge or miss it");
  cmd->add_option("--cut", args->cut,
                  "A closed surface (a bead, a figurine) is cut into charts by a plane across this axis through its "
                  "centre: auto (its longest axis), x, y or z; default: the design's placement.cut_axis, else auto");
  cmd->add_option("--spacing", args->spacing, "Edge length D in surface units (default: from the surface size)");
  cmd->add_option("--gap", args->gap,
                  "Required free space between neighbouring elements, surface units (default 0: touching)");
  cmd->add_option("--margin", args->margin,
                  "Free band along the surface's boundary that no element may enter, surface units (default 0)");
  cmd->add_option("--rim-rows", args->rim_rows,
                  "A row of stones that follows a rim, so a hole's edge looks designed, not trimmed: none (default), "
                  "holes (every loop but the outer edge) or all");
  cmd->add_flag("--beads", args->beads,
                "Add a bead (shared prong) in the gap between every three stones in contact; scale in the design "
                "file (elements.beads.scale)");
  cmd->add_option("--stone", args->stone,
                  "Stone diameter, surface units: the vertex elements become round brilliants of this size, with "
                  "D = stone + gap so that neighbouring stones are exactly the gap apart (instead of --spacing)");
  cmd->add_option("--units", args->units, "Unit of the surface's coordinates: mm (default), cm, m or in; stone sizes "
                                          "and carats are reported in mm");
  cmd->add_option("--out", args->out, "Output folder")->capture_default_str();
  cmd->add_flag("--no-optimize", args->no_optimize, "Skip the section 5 optimizer (initial pavement only)");
  cmd->add_flag("--no-postprocess", args->no_postprocess, "Skip boundary filling and elimination (5.4)");
  cmd->add_option("--threads", args->threads, "Solver threads (0 = all cores; no more than the cores are used)")->check(CLI::Range(0, 1024));
  app::add_backend_option(*cmd, args->backend);
  cmd->add_option("--device", args->device, "Vulkan device: a substring of its name (see `paver devices`)");
  cmd->add_flag("--quiet", args->quiet, "No progress on stderr (warnings and errors still)");
  cmd->add_option("--formats", args->formats,
                  "Mesh files to write, comma-separated: ply, obj, stl, glb (glTF 2.0 binary), 3mf")
      ->capture_default_str();
  cmd->add_flag("--subtract", args->subtract,
                "Also write the metal with the stones' seats cut out (cut.stl, cut.3mf) and its weight; needs --thickness");
  cmd->add_option("--thickness", args->thickness, "Metal thickness for --subtract, surface units (against the normals)");
  cmd->add_option("--cutter", args->cutter, "What --subtract cuts: seat (girdle, seat cone, hole through) or element")
      ->capture_default_str();
  cmd->add_flag("--png", args->png, "Also render preview.png (3D) and param.png (2D) offscreen with Vulkan");
  cmd->add_option("--max-output-gb", args->max_output_gb,
                  "Refuse to write element meshes (PLY + OBJ) larger than this, in GB")
      ->check(CLI::Range(0.001, 1e6))
      ->capture_default_str();
  // Every section 5 parameter from the one table, named as in design.json's "solver" object.
  cmd->add_flag("--no-resolve", args->no_resolve, "Skip the contact-spring collision resolution (with --no-refill: the paper's method only)");
  cmd->add_flag("--no-refill", args->no_refill, "Leave bare regions bare (no elements added where the pattern tore)");
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
