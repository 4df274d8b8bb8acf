#include "pipeline/run_pipeline.h"

#include "pattern/grade_field.h"

#include "core/input_error.h"
#include "core/interrupted.h"
#include "core/number_text.h"
#include "core/stopwatch.h"
#include "design/design_keys.h"
#include "elements/beads.h"
#include "elements/rim_rows.h"
#include "io/coordinate_precision.h"
#include "io/element_export.h"
#include "io/output_guard.h"
#include "map/surface_charts.h"
#include "io/output_set.h"
#include "pattern/grade_field.h"
#include "pattern/pattern.h"
#include "pipeline/choices.h"
#include "pipeline/map_surface.h"
#include "pipeline/run_outputs.h"
#include "report/verdict.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>
#include <utility>

namespace paver {
namespace {

using Warn = std::function<void(const std::string&)>;

// The output bound, checked twice: from the pattern before the solve (so that a design whose
// files would be too large is refused before the expensive work) and on the final elements
// (boundary filling and refill add a few).
void refuse_large_output(const ElementMeshSize& size, const PipelineRequest& request, const SurfaceMesh& surface) {
  const double bytes = expected_mesh_bytes(size, request.formats, surface);
  if (bytes <= request.max_output_bytes) return;
  throw InputError("the mesh files would take about " + significant_text(bytes / 1e9) + " GB (" +
                   std::to_string(size.elements) + " elements, " + std::to_string(size.faces) +
                   " triangles); the limit is " + significant_text(request.max_output_bytes / 1e9) +
                   " GB: use a lighter element shape, a larger spacing or fewer elements, or raise the limit "
                   "(--max-output-gb)");
}

// Runs `check`, naming the design file in front of a DesignError (the pattern's cell, its
// elements' overlaps, its edits), as the file's own validation does: the user has to know which
// file to open, and which of the options given with it changed it.
template <class Check>
auto naming_the_design_file(const PipelineRequest& request, Check&& check) {
  try {
    return check();
  } catch (const DesignError& e) {
    if (request.design_path.empty() && request.design_overrides.empty()) throw;
    std::string source = request.design_path.string();
    if (!request.design_overrides.empty()) source += (source.empty() ? "" : " with ") + request.design_overrides;
    throw DesignError(source + ": " + e.what());
  }
}

// What placement.align could not do well: a band's rows close around it instead, an axis that
// meets the surface steeply, or one whose direction turns over the map (a vase around the other
// axis): rows that do not follow it, said rather than printed as "rows along x".
std::vector<std::string> row_alignment_warnings(AlignAxis asked, const Pavement& pavement) {
  std::vector<std::string> out;
  if (asked == AlignAxis::None) return out;
  const std::string align = key_and_flag(Key::align) + " " + std::string(enum_name(asked));
  if (pavement.seamless) {
    out.push_back(align + " is not used: this band is paved seamlessly, and its rows close around it (" +
                  key_path(Key::band_rows) + " says which way)");
    return out;
  }
  const auto& a = pavement.row_alignment;
  if (!a) return out;
  if (a->axis_to_surface_deg > kAlignSteepWarnDeg)
    out.push_back(align + ": the axis meets this surface at " + std::to_string(std::lround(a->axis_to_surface_deg)) +
                  " degrees on average (90 = along its normal), so rows "
                  "along it follow only the surface's slope; an axis lying in the surface does better");
  if (a->spread_deg > kAlignSpreadWarnDeg)
    out.push_back(align + ": the axis's direction turns by about " + std::to_string(std::lround(a->spread_deg)) +
                  " degrees over this surface's map, so one turn of the pattern "
                  "lays only some of its rows along it (a surface wrapped around another axis: try that axis)");
  return out;
}

// A band's width across (its area over its rims' mean length): what a stone must fit in. Empty
// for other surfaces, and for a sheet with a hole, whose rims are no band's.
std::string band_width_text(const SurfaceMap& map) {
  if (!band_rims_alike(map)) return "";  // a band, and not a sheet with a hole
  const SurfaceMesh& m = map.mesh;
  const double rims =
      0.5 * (loop_length(m.positions, m.boundary_loops[0]) + loop_length(m.positions, m.boundary_loops[1]));
  if (!(rims > 0)) return "";
  // An estimate: three digits.
  return "; the band is about " + significant_text(surface_area(m) / rims) + " across, its area over its rims' mean length";
}

// placement.fit_offset where no lattice is laid over the map to shift (a band paved seamlessly,
// whose rows are shifted across it for the most elements anyway, and an adaptive pattern), or
// where element edits name the elements of the lattice at the design's offset.
std::optional<std::string> offset_fit_warning(const Design& design, const Pavement& pavement) {
  if (!design.placement.fit_offset || pavement.offset_fit) return std::nullopt;
  const std::string unused = key_and_flag(Key::fit_offset) + " is not used: ";
  if (pavement.seamless)
    return unused + "this band is paved seamlessly, and its rows are shifted across it for the most elements already";
  if (pavement.design.pattern.topology == Topology::Adaptive)
    return unused + "the adaptive pattern is grown over the surface, not laid as a lattice that a shift could move";
  if (!design.edits.empty())
    return unused + "this design's element edits name the elements of the lattice at its offset (" +
           key_path(Key::placement_offset) +
           "); fit the offset first, then edit (the studio keeps the fitted offset "
           "in the design at the first edit)";
  return std::nullopt;
}

// The longest axis is the usual best cut of a closed surface, not always: a bead cut across it kept
// a bare belt along the seam (fill 0.83, NOT OK) where a cut across x gave 0.86 and ok. When the
// first cut's pavement is NOT OK, the three axes are tried and the best kept; the kept design names
// its axis, so that its design.json repeats it without the tries.
void try_other_cut_axes(const PipelineRequest& request, const Design& design, const SurfaceMesh& closed,
                        PipelineResult& result) {
  if (judge_pavement(result.pavement.after).ok) return;
  const Stopwatch watch;
  const std::atomic<bool>* stop = request.pavement.stop;
  std::vector<std::shared_ptr<const SurfaceMap>> maps = {result.map};
  // A surface with handles was cut automatically where the plane runs through all of them.
  const std::string first_cut =
      closed_surface_handles(closed) == 0 ? "the longest axis" : "the axis that cuts through its handles";
  std::vector<Candidate> candidates = {{"longest", [&](const Pavement*) { return std::move(result.pavement); }, {}}};
  for (const CutAxis axis : {CutAxis::X, CutAxis::Y, CutAxis::Z}) {
    candidates.push_back({std::string(enum_name(axis)),
                          [&, axis, index = maps.size()](const Pavement*) {
                            auto map = map_closed_mesh(closed, request.surface_path, axis, {},
                                                       [&] { return stop && stop->load(); });
                            if (!map) return Pavement{};  // stopped: the caller ends the run
                            maps[index] = map;
                            Design cut = design;
                            cut.placement.cut_axis = axis;
                            return make_pavement(*map, cut, request.pavement);
                          },
                          // A ring's charts across some axes keep its handle: not a pavement.
                          [&closed, axis](const Pavement&) { return cuts_into_charts(closed, axis); }});
    maps.emplace_back();
  }
  const double first_ms = [&] {
    double ms = 0;
    for (const auto& [stage, stage_ms] : result.pavement.timings) ms += stage_ms;
    return ms;
  }();
  const std::size_t first_problems = judge_pavement(result.pavement.after).problems.size();
  const double first_fill = result.pavement.after.fill;
  Choice choice = best_of(candidates, stop);
  if (stop && stop->load()) return;
  result.pavement = std::move(choice.kept);
  result.map = maps[std::size_t(choice.kept_index)];
  const auto rounded = [](double fill) { return number_text(std::round(fill * 1000) / 1000); };
  if (choice.kept_index == 0) {
    result.cut_axis_choice = first_cut + ": no other cut did better";
  } else {
    const std::string axis = candidates[std::size_t(choice.kept_index)].name;
    result.cut_axis_choice = axis + ": cut across " + first_cut + ", the pavement had " +
                             count_text(first_problems, "problem", "problems") + " (fill " + rounded(first_fill) +
                             "); across " + axis + ", " +
                             count_text(judge_pavement(result.pavement.after).problems.size(), "problem", "problems") +
                             " (fill " + rounded(result.pavement.after.fill) + ")";
  }
  // Every try is counted once: a discarded first pavement's stages here, the kept one's as stages.
  double kept_ms = 0;
  for (const auto& [stage, ms] : result.pavement.timings) kept_ms += ms;
  result.timings.emplace_back("cut_axes_tried",
                              watch.milliseconds() - (choice.kept_index == 0 ? 0 : kept_ms - first_ms));
}

// The run's own checks, before any work: the design and its cell, its custom shape, and that no
// output would replace an input or a file of the user's. Returns the design's cell.
UnitCell check_request(PipelineRequest& request, PipelineResult& result, const Warn& warn) {
  const Design& design = request.design;
  // NaN passed every comparison and ended in "the limit is -nan GB" after the work.
  if (!(request.max_output_bytes > 0))
    throw InputError("the output size limit (--max-output-gb) is " + number_text(request.max_output_bytes / 1e9) +
                     " GB; give a positive number");
  validate_design(design, request.design_source);
  UnitCell cell = naming_the_design_file(request, [&] { return check_design_cell(design); });
  result.info = RunInfo{request.surface_path.string(), request.design_source, design.pattern.spacing <= 0,
                        request.surface_region};
  if (uses_custom_shape(design.elements)) {
    result.custom_shape = request.custom_shape
                              ? std::move(request.custom_shape)
                              : std::make_shared<const ShapeMesh>(load_custom_shape(design.elements.custom_shape));
    if (const long open = open_edge_count(*result.custom_shape); open > 0)
      warn("custom shape " + design.elements.custom_shape + ": " + count_text(open, "edge has", "edges have") +
           " one face only, so every element is exported as an open surface, which a printer or a boolean cannot "
           "take; close the shape in the modelling tool");
  }
  if (request.out)
    check_run_outputs(*request.out, request.formats, request.extra_outputs,
                      {request.surface_path, request.design_path, design.elements.custom_shape});
  return cell;
}

// The surface loaded and mapped, or the caller's map. A spacing far too small for the surface's
// area is refused before the map (a minute on a million faces). The map's area equals the
// surface's (scale_to_surface_area) up to a band's closure and an atlas's seams: twice the limit
// leaves the borderline to build_pattern.
std::shared_ptr<const SurfaceMesh> map_the_surface(PipelineRequest& request, PipelineResult& result,
                                                   const UnitCell& cell) {
  const Design& design = request.design;
  if (request.map) {
    result.map = std::move(request.map);
    result.timings = std::move(request.map_timings);
    return nullptr;
  }
  const std::atomic<bool>* stop = request.pavement.stop;
  // What the loaded mesh refuses, before the map is made (minutes on a large scan).
  const auto refuse_tiny_spacing = [&](const SurfaceMesh& mesh) {
    if (design.pattern.spacing > 0) refuse_too_many_points(surface_area(mesh), cell, design.placement, 2);
    refuse_rim_grade_without_rims(design, !mesh.boundary_loops.empty());
  };
  MappedSurface mapped = map_surface_file(
      request.surface_path, request.progress, [&] { return stop && stop->load(); }, request.on_warning,
      design.placement.cut_axis, refuse_tiny_spacing, request.surface_region);
  result.map = std::move(mapped.map);
  result.warnings = std::move(mapped.warnings);
  result.timings = std::move(mapped.timings);
  return std::move(mapped.closed_surface);
}

// What the design asks that this surface does not use, said before the pattern.
void warn_about_surface(const Design& design, const SurfaceMap& map, const Warn& warn) {
  if (design.placement.cut_axis != CutAxis::Auto && !is_atlas(map))
    warn(key_and_flag(Key::cut_axis) + " " + std::string(enum_name(design.placement.cut_axis)) +
         " is for a closed surface, which is cut into charts; this one is open, so it is not used");
  if (design.elements.margin > 0 && is_atlas(map))
    warn(key_and_flag(Key::margin) + " " + number_text(design.elements.margin) +
         " keeps stones off a surface's rims; this surface is closed (its charts' seams are no rims), so it is not "
         "used");
}

// The mesh files' size before the pattern, which on a band lays out dozens of tries while it
// closes and shifts (36 s for 15 GB of files on a ring before the refusal): the vertex elements
// alone, from the map's area, at half their estimate, so that only a clear excess is refused
// here; the pattern's own count decides the rest (the pattern hook, below).
void refuse_large_output_early(PipelineRequest& request, const PipelineResult& result, const UnitCell& cell) {
  const Design& design = request.design;
  if (request.out && design.pattern.spacing > 0 && design.elements.vertex.enabled &&
      design.elements.vertex.shape != ShapeKind::Custom) {
    refuse_too_many_points(surface_area(result.map->mesh), cell, design.placement);  // its own message first
    const auto n = static_cast<std::size_t>(0.5 * estimate_point_count(*result.map, cell, design.placement));
    refuse_large_output(shape_mesh_size(design.elements.vertex.shape, n), request, result.map->mesh);
  }
  if (!request.out) return;
  std::function<void(const Pattern&, const Design&)> caller_hook = std::move(request.pavement.on_pattern);
  request.pavement.on_pattern = [&request, &result, caller_hook](const Pattern& pattern, const Design& used) {
    refuse_large_output(expected_element_mesh_size(pattern, used.elements, {.custom = result.custom_shape.get()}),
                        request, result.map->mesh);
    if (caller_hook) caller_hook(pattern, used);
  };
}

// Elements so small beside the part's coordinates that a mesh file's 32-bit numbers cannot draw
// them (an element scale of 1e-300 wrote zero-size elements): refused once the pattern's D is
// known, before the solves. 2^-17 of the largest coordinate leaves an element some 128 steps of
// float32 across.
void refuse_elements_too_small(PipelineRequest& request, const PipelineResult& result) {
  double largest = 0;
  for (const glm::dvec3& p : result.map->mesh.positions)
    largest = std::max({largest, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  std::function<void(const Pattern&, const Design&)> caller_hook = std::move(request.pavement.on_pattern);
  request.pavement.on_pattern = [largest, caller_hook](const Pattern& pattern, const Design& used) {
    const double smallest_drawn = largest * std::ldexp(1.0, -17);
    const auto refuse_below = [&](Key key, double scale) {
      const double diameter = scale * used.pattern.spacing;
      if (diameter >= smallest_drawn) return;
      throw InputError(key_path(key) + " " + number_text(scale) + ": the elements would be " + number_text(diameter) +
                       " surface units across (scale x D = " + number_text(used.pattern.spacing) +
                       "), too small to draw in a mesh file beside coordinates of up to " + number_text(largest) +
                       " (at least " + number_text(smallest_drawn) + " is needed); use a larger scale or spacing");
    };
    if (used.elements.vertex.enabled) refuse_below(Key::vertex_scale, used.elements.vertex.scale);
    for (const EdgeElementDesign& edge : used.elements.edge) refuse_below(Key::edge_scale, edge.scale);
    if (caller_hook) caller_hook(pattern, used);
  };
}

// What the pavement did not use of the design, or did in a way the user should hear of.
void warn_about_pavement(const Design& design, const PipelineResult& result, const Warn& warn) {
  for (const std::string& w : row_alignment_warnings(design.placement.align, result.pavement)) warn(w);
  if (const auto w = offset_fit_warning(design, result.pavement)) warn(*w);
  if (const auto w = fine_beads_warning(result.pavement.beads, result.pavement.design.units)) warn(*w);
  if (result.pavement.design.elements.beads.enabled)
    if (const auto w = underheld_stones_warning(result.pavement.elements,
                                                measure_bead_hold(result.pavement.elements, result.pavement.beads)))
      warn(*w);
  const Pavement& p = result.pavement;
  if (p.spots_closed.too_many_stones && p.after.edges.bare_spots > 0)
    warn(key_and_flag(Key::close_spots) + ": the bare spots of a pavement of " + std::to_string(p.elements.size()) +
         " stones are not closed (the closing packs each spot on its own; up to " +
         std::to_string(kMostStonesClosed) + " stones): the verdict names them");
  if (design.elements.rim_rows == RimRows::Holes && band_rims_alike(*result.map))
    warn(key_and_flag(Key::rim_rows) +
         " holes: this band's two rims are its edges, not a hole, so no row is laid; "
         "--" +
         std::string(design_key(Key::rim_rows).flag) + " all lines both");
}

// A pavement with no element is no result: why, and what to change.
void refuse_empty_pavement(const PipelineResult& result) {
  if (result.pavement.elements.size() > 0) return;
  const Pavement& p = result.pavement;
  const long deleted = long(p.design.edits.deleted.size()) - long(p.deletions_missed);
  if (deleted > 0)
    throw InputError("no element is left: '" + key_path(Key::edits_deleted) + "' deletes every one of the " +
                     count_text(deleted, "element", "elements") + " the pattern placed; delete fewer");
  const double margin = is_atlas(*result.map) ? 0 : p.design.elements.margin;  // none on a closed surface
  const std::string why = p.eliminated == 0 ? "was dropped"
                          : margin > 0      ? "crossed its boundary or the margin along it"
                                            : "crossed its boundary (the surface is narrower than the elements" +
                                             band_width_text(*result.map) + ")";
  const std::string what_to_do = margin > 0 ? "use a smaller margin (--" + std::string(design_key(Key::margin).flag) +
                                                  ", " + key_path(Key::margin) + ": now " + number_text(margin) +
                                                  "), smaller stones or a smaller spacing"
                                            : "use smaller stones (--stone, the element scales) or a smaller spacing";
  throw InputError("no element fits on this surface: the pattern put " +
                   count_text(p.pattern.point_count(), "point", "points") + " on it " +
                   (p.band_closure ? "(the band closed at " + describe_band_closure(*p.band_closure) + ")"
                                   : "at D = " + number_text(p.design.pattern.spacing)) +
                   ", and every element " + why + "; " + what_to_do);
}

// The run's files, published as one set (write_run_outputs), after the last size check.
void export_outputs(PipelineRequest& request, PipelineResult& result, const Warn& warn) {
  refuse_large_output(element_mesh_size(result.pavement.elements, {.custom = result.custom_shape.get()}), request,
                      result.map->mesh);
  const auto extras = [&](const std::filesystem::path& folder, StageTimings& timings, nlohmann::json& sections) {
    if (request.write_extras) request.write_extras(result, folder, timings, sections);
  };
  // STL and 3MF round coordinates: say so when that moves a part far from the origin.
  if (const std::string w =
          coordinate_rounding_warning(result.pavement.elements, request.formats.stl ? "elements.stl" : "",
                                      request.formats.threemf ? "paved.3mf" : "");
      !w.empty())
    warn(w);
  if (request.on_export) request.on_export();
  const std::vector<std::string> untidy =
      write_run_outputs(*request.out, result.info, *result.map, result.pavement, result.timings,
                        {.custom = result.custom_shape.get(), .formats = request.formats, .stop = request.pavement.stop},
                        extras);
  for (const std::string& w : untidy) warn(w);
}

}  // namespace

PipelineResult run_pipeline(PipelineRequest request) {
  PipelineResult result;
  const Design& design = request.design;
  // A warning known to the run: kept with the result and told to the caller at once.
  const Warn warn = [&](const std::string& warning) {
    result.warnings.push_back(warning);
    if (request.on_warning) request.on_warning(warning);
  };
  const UnitCell cell = check_request(request, result, warn);
  const std::atomic<bool>* stop = request.pavement.stop;
  const auto check_stop = [&] {
    if (stop && stop->load()) throw Interrupted();
  };
  const std::shared_ptr<const SurfaceMesh> closed_surface = map_the_surface(request, result, cell);
  check_stop();
  warn_about_surface(design, *result.map, warn);
  if (request.check_map) request.check_map(*result.map);
  refuse_large_output_early(request, result, cell);
  refuse_elements_too_small(request, result);
  result.pavement =
      naming_the_design_file(request, [&] { return make_pavement(*result.map, design, request.pavement); });
  check_stop();  // the solves ended early: a partial pavement is not a result
  if (closed_surface && design.placement.cut_axis == CutAxis::Auto)
    try_other_cut_axes(request, design, *closed_surface, result);
  check_stop();
  warn_about_pavement(design, result, warn);
  refuse_empty_pavement(result);
  result.timings.insert(result.timings.end(), result.pavement.timings.begin(), result.pavement.timings.end());
  result.counts = count_pavement(result.pavement);
  if (request.out) export_outputs(request, result, warn);
  return result;
}

}  // namespace paver
