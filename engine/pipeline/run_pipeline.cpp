#include "pipeline/run_pipeline.h"

#include "core/input_error.h"
#include "core/interrupted.h"
#include "core/number_text.h"
#include "io/coordinate_precision.h"
#include "io/output_guard.h"
#include "io/output_set.h"
#include "pipeline/run_outputs.h"
#include "pipeline/map_surface.h"
#include "pattern/pattern.h"
#include "core/stopwatch.h"
#include "elements/beads.h"
#include "elements/rim_rows.h"
#include "report/verdict.h"

#include "io/element_export.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <optional>

#include <utility>

namespace paver {
namespace {

// The output bound, checked twice: from the pattern before the solve (so that a design whose
// files would be too large is refused before the expensive work) and on the final elements
// (boundary filling and refill add a few).
void refuse_large_output(const ElementMeshSize& size, const PipelineRequest& request, const SurfaceMesh& surface) {
  const double bytes = expected_mesh_bytes(size, request.formats, surface);
  if (bytes <= request.max_output_bytes) return;
  char text[320];
  std::snprintf(text, sizeof text,
                "the mesh files would take about %.3g GB (%zu elements, %zu triangles); the limit is %.3g GB: "
                "use a lighter element shape, a larger spacing or fewer elements, or raise the limit (--max-output-gb)",
                bytes / 1e9, size.elements, size.faces, request.max_output_bytes / 1e9);
  throw InputError(text);
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
    if (!request.design_overrides.empty())
      source += (source.empty() ? "" : " with ") + request.design_overrides;
    throw DesignError(source + ": " + e.what());
  }
}

// What placement.align could not do well: a band's rows close around it instead, an axis that
// meets the surface steeply, or one whose direction turns over the map (a vase around the other
// axis): rows that do not follow it, said rather than printed as "rows along x".
std::vector<std::string> row_alignment_warnings(AlignAxis asked, const Pavement& pavement) {
  std::vector<std::string> out;
  if (asked == AlignAxis::None) return out;
  const std::string axis = std::string(enum_name(asked));
  if (pavement.seamless) {
    out.push_back("placement.align (--align) " + axis + " is not used: this band is paved seamlessly, and its rows "
                  "close around it (placement.band_rows says which way)");
    return out;
  }
  const auto& a = pavement.row_alignment;
  if (!a) return out;
  if (a->axis_to_surface_deg > kAlignSteepWarnDeg)
    out.push_back("placement.align (--align) " + axis + ": the axis meets this surface at " +
                  std::to_string(std::lround(a->axis_to_surface_deg)) + " degrees on average (90 = along its normal), so rows "
                  "along it follow only the surface's slope; an axis lying in the surface does better");
  if (a->spread_deg > kAlignSpreadWarnDeg)
    out.push_back("placement.align (--align) " + axis + ": the axis's direction turns by about " +
                  std::to_string(std::lround(a->spread_deg)) + " degrees over this surface's map, so one turn of the pattern "
                  "lays only some of its rows along it (a surface wrapped around another axis: try that axis)");
  return out;
}

// A band's width across (its area over its rims' mean length): what a stone must fit in. Empty
// for other surfaces, and for a sheet with a hole, whose rims are no band's.
std::string band_width_text(const SurfaceMap& map) {
  if (!band_rims_alike(map)) return "";  // a band, and not a sheet with a hole
  const SurfaceMesh& m = map.mesh;
  const double rims = 0.5 * (loop_length(m.positions, m.boundary_loops[0]) + loop_length(m.positions, m.boundary_loops[1]));
  if (!(rims > 0)) return "";
  char across[32];
  std::snprintf(across, sizeof across, "%.3g", surface_area(m) / rims);  // an estimate: three digits
  return "; the band is about " + std::string(across) + " across, its area over its rims' mean length";
}

// placement.fit_offset where no lattice is laid over the map to shift (a band paved seamlessly,
// whose rows are shifted across it for the most elements anyway, and an adaptive pattern), or
// where element edits name the elements of the lattice at the design's offset.
std::optional<std::string> offset_fit_warning(const Design& design, const Pavement& pavement) {
  if (!design.placement.fit_offset || pavement.offset_fit) return std::nullopt;
  if (pavement.seamless)
    return "placement.fit_offset (--fit-offset) is not used: this band is paved seamlessly, and its rows are "
           "shifted across it for the most elements already";
  if (pavement.design.pattern.topology == Topology::Adaptive)
    return "placement.fit_offset (--fit-offset) is not used: the adaptive pattern is grown over the surface, not "
           "laid as a lattice that a shift could move";
  if (!design.edits.empty())
    return "placement.fit_offset (--fit-offset) is not used: this design's element edits name the elements of the "
           "lattice at its offset (placement.offset); fit the offset first, then edit (the studio keeps the fitted "
           "offset in the design at the first edit)";
  return std::nullopt;
}

// The longest axis is the usual best cut of a closed surface, not always: a bead cut across it kept
// a bare belt along the seam (fill 0.83, NOT OK) where a cut across x gave 0.86 and ok. When the
// first cut's pavement is NOT OK, the three axes are tried and the best kept; the kept design names
// its axis, so that its design.json repeats it without the tries.
void try_other_cut_axes(const PipelineRequest& request, const Design& design, const SurfaceMesh& closed,
                        PipelineResult& result) {
  const auto score = [](const Pavement& p) {
    return std::make_pair(-int(judge_pavement(p.after).problems.size()), p.after.fill);
  };
  const auto first = score(result.pavement);
  if (first.first == 0) return;
  const Stopwatch watch;
  const auto stages_ms = [](const Pavement& p) {
    double ms = 0;
    for (const auto& [stage, stage_ms] : p.timings) ms += stage_ms;
    return ms;
  };
  const double first_ms = stages_ms(result.pavement);
  auto best = first;
  std::string why;
  const std::atomic<bool>* stop = request.pavement.stop;
  for (const CutAxis axis : {CutAxis::X, CutAxis::Y, CutAxis::Z}) {
    if (stop && stop->load()) return;
    std::shared_ptr<const SurfaceMap> map =
        map_closed_mesh(closed, request.surface_path, axis, {}, [&] { return stop && stop->load(); });
    if (!map) return;
    Design cut = design;
    cut.placement.cut_axis = axis;
    Pavement pavement = make_pavement(*map, cut, request.pavement);
    const auto tried = score(pavement);
    if (tried <= best) continue;
    best = tried;
    why = std::string(enum_name(axis)) + ": cut across the longest axis, the pavement had " +
          count_text(-first.first, "problem", "problems") + " (fill " + number_text(std::round(first.second * 1000) / 1000) +
          "); across " + std::string(enum_name(axis)) + ", " + count_text(-tried.first, "problem", "problems") +
          " (fill " + number_text(std::round(tried.second * 1000) / 1000) + ")";
    result.map = std::move(map);
    result.pavement = std::move(pavement);
  }
  result.cut_axis_choice = why.empty() ? "the longest axis: no other cut did better" : why;
  // Every try is counted once: a discarded first pavement's stages here, the kept one's as stages.
  const double kept_ms = why.empty() ? 0 : stages_ms(result.pavement) - first_ms;
  result.timings.emplace_back("cut_axes_tried", watch.milliseconds() - kept_ms);
}

}  // namespace

PipelineResult run_pipeline(PipelineRequest request) {
  PipelineResult result;
  const Design& design = request.design;
  validate_design(design, request.design_source);
  const UnitCell cell = naming_the_design_file(request, [&] { return check_design_cell(design); });
  result.info = RunInfo{request.surface_path.string(), request.design_source, design.pattern.spacing <= 0};
  // A warning known to the run: kept with the result and told to the caller at once.
  const auto warn = [&](const std::string& warning) {
    result.warnings.push_back(warning);
    if (request.on_warning) request.on_warning(warning);
  };
  if (uses_custom_shape(design.elements)) {
    result.custom_shape = request.custom_shape ? std::move(request.custom_shape)
                                               : std::make_shared<const ShapeMesh>(
                                                     load_custom_shape(design.elements.custom_shape));
    if (const long open = open_edge_count(*result.custom_shape); open > 0) {
      const std::string warning = "custom shape " + design.elements.custom_shape + ": " +
                                  count_text(open, "edge has", "edges have") +
                                  " one face only, so every element is exported as an open surface, which a printer "
                                  "or a boolean cannot take; close the shape in the modelling tool";
      warn(warning);
    }
  }

  // Refuse before any work if an output would replace an input.
  std::vector<std::filesystem::path> outputs;
  if (request.out) {
    outputs = run_output_paths(*request.out, request.formats);
    outputs.insert(outputs.end(), request.extra_outputs.begin(), request.extra_outputs.end());
    refuse_overwriting_inputs({request.surface_path, request.design_path, design.elements.custom_shape}, outputs);
    check_output_folder(*request.out);
    OutputSet::refuse_replacing_users_files(*request.out, outputs, run_output_names());
  }

  const std::atomic<bool>* stop = request.pavement.stop;
  const auto check_stop = [&] {
    if (stop && stop->load()) throw Interrupted();
  };
  // A spacing far too small for the surface's area is refused before the map (a minute on a
  // million faces). The map's area equals the surface's (scale_to_surface_area) up to a band's
  // closure and an atlas's seams: twice the limit leaves the borderline to build_pattern.
  const auto refuse_tiny_spacing = [&](const SurfaceMesh& mesh) {
    if (design.pattern.spacing > 0) refuse_too_many_points(surface_area(mesh), cell, design.placement, 2);
  };
  std::shared_ptr<const SurfaceMesh> closed_surface;  // as loaded: another cut maps it again
  if (request.map) {
    result.map = std::move(request.map);
    result.timings = std::move(request.map_timings);
  } else {
    const StopRequested stop_requested = [&] { return stop && stop->load(); };
    MappedSurface mapped =
        map_surface_file(request.surface_path, request.progress, stop_requested, request.on_warning,
                         design.placement.cut_axis, refuse_tiny_spacing);
    result.map = std::move(mapped.map);
    result.warnings = std::move(mapped.warnings);
    result.timings = std::move(mapped.timings);
    closed_surface = std::move(mapped.closed_surface);
  }
  check_stop();
  if (design.placement.cut_axis != CutAxis::Auto && result.map && !is_atlas(*result.map)) {
    const std::string unused = "placement.cut_axis (--cut) " + std::string(enum_name(design.placement.cut_axis)) +
                               " is for a closed surface, which is cut into charts; this one is open, so it is not used";
    warn(unused);
  }
  if (design.elements.margin > 0 && result.map && is_atlas(*result.map))
    warn("elements.margin (--margin) " + number_text(design.elements.margin) +
         " keeps stones off a surface's rims; this surface is closed (its charts' seams are no rims), so it is not "
         "used");
  // The mesh files' size before the pattern, which on a band lays out dozens of tries while it
  // closes and shifts (36 s for 15 GB of files on a ring before the refusal): the vertex elements
  // alone, from the map's area, at half their estimate, so that only a clear excess is refused
  // here; the pattern's own count decides the rest (on_pattern below).
  if (request.out && design.pattern.spacing > 0 && design.elements.vertex.enabled &&
      design.elements.vertex.shape != ShapeKind::Custom) {
    refuse_too_many_points(surface_area(result.map->mesh), cell, design.placement);  // its own message first
    const auto n = static_cast<std::size_t>(0.5 * estimate_point_count(*result.map, cell, design.placement));
    refuse_large_output(shape_mesh_size(design.elements.vertex.shape, n), request, result.map->mesh);
  }

  if (request.out) {
    std::function<void(const Pattern&, const Design&)> caller_hook = std::move(request.pavement.on_pattern);
    request.pavement.on_pattern = [&, caller_hook](const Pattern& pattern, const Design& used) {
      refuse_large_output(expected_element_mesh_size(pattern, used.elements, {.custom = result.custom_shape.get()}),
                          request, result.map->mesh);
      if (caller_hook) caller_hook(pattern, used);
    };
  }
  result.pavement = naming_the_design_file(request, [&] { return make_pavement(*result.map, design, request.pavement); });
  check_stop();  // the solves ended early: a partial pavement is not a result
  for (const std::string& w : row_alignment_warnings(design.placement.align, result.pavement)) warn(w);
  if (const auto w = offset_fit_warning(design, result.pavement)) warn(*w);
  if (closed_surface && design.placement.cut_axis == CutAxis::Auto)
    try_other_cut_axes(request, design, *closed_surface, result);
  if (const auto w = fine_beads_warning(result.pavement.beads, result.pavement.design.units)) warn(*w);
  if (design.elements.rim_rows == RimRows::Holes && band_rims_alike(*result.map))
    warn("elements.rim_rows (--rim-rows) holes: this band's two rims are its edges, not a hole, so no row is laid; "
         "--rim-rows all lines both");
  if (result.pavement.elements.size() == 0) {
    const Pavement& p = result.pavement;
    const double margin = is_atlas(*result.map) ? 0 : p.design.elements.margin;  // none on a closed surface
    const std::string why = p.eliminated == 0 ? "was dropped"
                            : margin > 0     ? "crossed its boundary or the margin along it"
                                             : "crossed its boundary (the surface is narrower than the elements" +
                                                   band_width_text(*result.map) + ")";
    const std::string what_to_do = margin > 0 ? "use a smaller margin (--margin, elements.margin: now " +
                                                    number_text(margin) + "), smaller stones or a smaller spacing"
                                              : "use smaller stones (--stone, the element scales) or a smaller spacing";
    throw InputError("no element fits on this surface: the pattern put " +
                     count_text(p.pattern.point_count(), "point", "points") + " on it " +
                     (p.band_closure ? "(the band closed at " + describe_band_closure(*p.band_closure) + ")"
                                     : "at D = " + number_text(p.design.pattern.spacing)) +
                     ", and every element " + why +
                     "; " + what_to_do);
  }
  result.timings.insert(result.timings.end(), result.pavement.timings.begin(), result.pavement.timings.end());
  result.counts = count_pavement(result.pavement);

  if (request.out) {
    refuse_large_output(element_mesh_size(result.pavement.elements, {.custom = result.custom_shape.get()}), request,
                        result.map->mesh);
    const auto extras = [&](const std::filesystem::path& folder, StageTimings& timings, nlohmann::json& sections) {
      if (request.write_extras) request.write_extras(result, folder, timings, sections);
    };
    // STL and 3MF round coordinates: say so when that moves a part far from the origin.
    if (const std::string w = coordinate_rounding_warning(result.pavement.elements, request.formats.stl ? "elements.stl" : "",
                                                          request.formats.threemf ? "paved.3mf" : "");
        !w.empty()) {
      warn(w);
    }
    if (request.on_export) request.on_export();
    write_run_outputs(*request.out, result.info, *result.map, result.pavement, result.timings,
                      {.custom = result.custom_shape.get(), .formats = request.formats, .stop = stop}, extras);
  }
  return result;
}

}  // namespace paver
