#include "run_summary.h"

#include "core/number_text.h"
#include "core/printable.h"
#include "design/design_keys.h"
#include "elements/beads.h"
#include "map/surface_charts.h"
#include "pattern/adaptive_pattern.h"
#include "report/bill_of_stones.h"
#include "report/verdict.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

namespace paver::cli {
namespace {

bool print_verdict(const PipelineResult& result, const nlohmann::json& cut) {
  const Pavement& pavement = result.pavement;
  Verdict verdict = judge_pavement(pavement.after);
  // The cut metal's production rules (--culet-clearance, --seat-wall, --table-height, a table sunk
  // by --seat-depth), when one is broken.
  if (cut.is_object() && cut.contains("seats"))
    for (const nlohmann::json& problem : cut["seats"]["problems"]) {
      verdict.ok = false;
      verdict.problems.push_back(problem.get<std::string>());
    }
  std::printf("verdict  %s\n", verdict.ok ? "ok: no contact violations, no boundary crossings, pattern intact"
                                          : "NOT OK:");
  for (const std::string& problem : verdict.problems) std::printf("         - %s\n", problem.c_str());
  // A lattice that tore or left bare patches is what the adaptive topology is for.
  const bool lattice_failed = pattern_is_torn(pavement.after) || has_bare_patches(pavement.after);
  // Not when auto tried the adaptive pattern already and it did no better (topology_choice says so).
  if (lattice_failed && pavement.design.pattern.topology == Topology::Lattice && pavement.topology_choice.empty() &&
      adaptive_pattern_unsupported(pavement.design).empty())
    std::printf("         hint: the map distorts the lattice here; --%s adaptive grows the pattern on the "
                "surface instead (docs/topology.md)\n",
                std::string(design_key(Key::pattern_topology).flag).c_str());
  if (result.info.spacing_derived)
    std::printf("no spacing given: using D = %g, about 1000 points over this surface\n",
                pavement.design.pattern.spacing);
  return verdict.ok;
}

void print_surface_and_map(const SurfaceMap& map, const std::string& surface) {
  const auto& q = map.parameterization.quality;
  const auto& pr = map.parameterization.report;
  const int holes = map.mesh.hole_count();
  const long long handles = closed_surface_handles(map.closed_surface_vertices, map.closed_surface_faces);
  const std::string handle_text = handles == 1 ? " with 1 handle" : handles > 1 ? " with " + std::to_string(handles) + " handles" : "";
  const std::string shape = is_atlas(map) ? "a closed surface" + handle_text + ", cut into " + std::to_string(chart_count(map)) +
                                                " charts (" + std::to_string(map.mesh.boundary_loops.size()) +
                                                " seam loops, each chart's side counted)"
                            : holes == 0 ? "a disk"
                            : holes == 1 ? "a band or a disk with a hole (2 boundary loops)"
                                         : std::to_string(holes) + " holes (" + std::to_string(holes + 1) + " boundary loops)";
  std::printf("surface  %s: %d vertices, %d faces, area %.6g, %s\n", printable(surface).c_str(),
              is_atlas(map) ? map.closed_surface_vertices : map.mesh.vertex_count(),
              is_atlas(map) ? map.closed_surface_faces : map.mesh.face_count(), surface_area(map.mesh), shape.c_str());
  std::printf("map      %s, %d iterations: %d flips, %d boundary overlaps, s1/s2 mean %.3f max %.3f\n",
              map_method_name(pr).c_str(), pr.iterations, q.flipped_triangles, q.boundary_intersections,
              q.stretch_mean, q.stretch_max);
}

void print_pattern(const Pavement& pavement, const PavementCounts& counts) {
  std::printf("pattern  %s %s, D = %g: %d points, %ld edges (+%ld virtual), %ld edges cross the boundary",
              std::string(enum_name(pavement.design.pattern.tessellation)).c_str(),
              std::string(enum_name(pavement.design.pattern.topology)).c_str(), pavement.design.pattern.spacing,
              pavement.pattern.point_count(), counts.pattern_edges, counts.virtual_edges,
              counts.boundary_crossing_edges);
  if (pavement.design.pattern.topology == Topology::Adaptive)
    std::printf("; %zu point defects, relaxed in %d iterations and packed in %d (%d jammed removed), %.0f ms",
                pavement.pattern.defects.size(), pavement.relaxation.iterations,
                pavement.relaxation.packing_iterations, pavement.relaxation.jammed, pavement.relaxation.milliseconds);
  if (const DefectHealingReport& healed = pavement.relaxation.healing; healed.tries > 0)
    std::printf("; interior defects healed %d -> %d (%d of %d shaken patches rearranged, %.0f ms)",
                healed.defects_before, healed.defects_after, healed.moved, healed.tries, healed.milliseconds);
  std::printf("\n");
}

// What the automatic choices chose: topology, cut axis, row alignment, offset, band closure.
void print_choices(const PipelineResult& result) {
  const SurfaceMap& map = *result.map;
  const Pavement& pavement = result.pavement;
  if (!pavement.topology_choice.empty()) std::printf("topology %s\n", pavement.topology_choice.c_str());
  if (!result.cut_axis_choice.empty()) std::printf("cut axis %s\n", result.cut_axis_choice.c_str());
  if (const auto& a = pavement.row_alignment) {
    char total[96] = "";
    if (pavement.design.placement.rotation_deg != a->rotation_deg)
      std::snprintf(total, sizeof total, ", %.1f with %s", pavement.design.placement.rotation_deg,
                    key_path(Key::rotation_deg).c_str());
    std::printf("align    rows along %s: the pattern turned %.1f degrees%s; the axis meets the surface at %.0f "
                "degrees on average and its direction on the map varies by %.1f degrees\n",
                std::string(enum_name(a->axis)).c_str(), std::abs(a->rotation_deg) < 0.05 ? 0.0 : a->rotation_deg,
                total, a->axis_to_surface_deg, a->spread_deg);
  }
  if (const auto& f = pavement.offset_fit) {
    const OffsetCandidate& c = f->chosen;
    std::printf("offset   fitted: the lattice shifted (%.4g, %.4g) cells to (%.4g, %.4g): ", c.shift_in_cells.x,
                c.shift_in_cells.y, c.offset.x, c.offset.y);
    if (c.kept >= 0)
      std::printf("%ld elements kept against %ld at the design's offset (the best of %zu shifts paved in full, out of "
                  "%d laid out)\n",
                  c.kept, f->at_design.kept, f->finalists.size(), f->tries);
    else
      std::printf("%zu elements laid out against %zu at the design's offset (the best of %d shifts; a pattern this "
                  "large is not paved at each)\n",
                  c.laid_out, f->at_design.laid_out, f->tries);
  }
  if (!is_band(map)) return;
  if (pavement.band_closure) {
    // The closure widens the lattice's gap; the pass brings stones back to contact where it can:
    // the gap they end at is what was ordered (issue 40, "stones as ordered").
    std::string ended;
    const PavementQuality& q = pavement.after;
    const std::optional<double> median_gap = median_neighbour_gap(q);
    if (pavement.band_closure->stones_kept && median_gap) {
      const double beyond = (*median_gap - pavement.band_closure->gap_asked) / pavement.band_closure->spacing_before;
      char text[96];
      std::snprintf(text, sizeof text, "; paved, the median gap between neighbours is %.4g (%+.1f%% of D)", *median_gap,
                    100 * beyond);
      ended = text;
    }
    std::printf("band     seamless (period %.6g, map s1/s2 mean %.3f): %s%s\n", map.seamless->period,
                map.seamless->parameterization.quality.stretch_mean,
                describe_band_closure(*pavement.band_closure).c_str(), ended.c_str());
  }
  else
    std::printf("band     paved as an annulus: %s\n", band_annulus_reason(map, pavement).c_str());
}

void print_optimize(const Pavement& pavement, const SummaryContext& context) {
  // The backend that ran the main solve: auto takes the CPU for a small system, and the adaptive
  // pattern's optimizer runs on the CPU whatever was asked.
  const std::string ran = pavement.solve.backend.empty() ? context.backend : pavement.solve.backend;
  const bool on_device = ran == "vulkan" && !context.device.empty();
  std::printf("optimize %s%s%s: %d iterations, %s (last max step %.3g); %d filled, %d eliminated at the boundary, "
              "%d removed still colliding\n",
              ran.c_str(), on_device ? " on " : "", on_device ? context.device.c_str() : "", pavement.solve.iterations,
              std::string(enum_name(pavement.solve.reason)).c_str(), pavement.solve.last_max_step, pavement.filled,
              pavement.eliminated, pavement.resolution.removed);
  if (!pavement.coarse_start.level_points.empty()) {
    std::printf("         multilevel start:");
    for (int points : pavement.coarse_start.level_points) std::printf(" %d", points);
    std::printf(" points, %d particles found no room\n", pavement.coarse_start.retired);
  }
  if (pavement.resolution.retired > 0)
    std::printf("         %d vacancies where contact springs stalled\n", pavement.resolution.retired);
  if (const ElementEdits& edits = pavement.design.edits; !edits.empty()) {
    std::printf("edits    %zu moved (%d pinned), %zu added, %zu deleted", edits.moved.size(), edits.pinned_count(),
                edits.added.size(), edits.deleted.size() - std::size_t(pavement.deletions_missed));
    if (pavement.deletions_missed > 0)
      std::printf("; %d deletions found no element (a refilled one the edits moved away)", pavement.deletions_missed);
    std::printf("\n");
  }
}

void print_elements(const SurfaceMap& map, const Pavement& pavement, const PavementCounts& counts) {
  std::printf("elements %zu (%ld V, %ld E%s), %d of them added into bare regions, %d into bare spots",
              pavement.elements.size(), counts.vertex_elements, counts.edge_elements,
              counts.pattern_faces > 0 ? (", " + std::to_string(counts.face_elements) + " F in " +
                                          std::to_string(counts.pattern_faces) + " faces").c_str()
                                       : "",
              pavement.refill.added,
              pavement.spots_closed.added);
  if (pavement.spots_closed.of_edge_size > 0)
    std::printf(" (%d of them of the E-elements' size)", pavement.spots_closed.of_edge_size);
  if (is_atlas(map)) std::printf(" (%d across the seams)", pavement.refill.on_seams);
  if (!pavement.size_fill.sizes.empty()) {
    std::printf(", %d of smaller stocked sizes (", pavement.size_fill.added());
    for (std::size_t k = 0; k < pavement.size_fill.sizes.size(); ++k)
      std::printf("%s%d of %s", k ? ", " : "", pavement.size_fill.sizes[k].added,
                  diameter_mm_text(pavement.size_fill.sizes[k].diameter * millimetres_per_unit(pavement.design.units)).c_str());
    std::printf(" mm)");
  }
  std::printf("\n");
  if (pavement.design.elements.grade.by != GradeBy::None && !pavement.grade.ladder.empty()) {
    const double mm = millimetres_per_unit(pavement.design.units);
    std::printf("graded by %s: %d stones under the main %s mm, down to %s mm in %zu steps\n",
                std::string(enum_name(pavement.design.elements.grade.by)).c_str(), pavement.grade.graded,
                diameter_mm_text(pavement.grade.ladder.front() * mm).c_str(),
                diameter_mm_text(pavement.grade.ladder.back() * mm).c_str(), pavement.grade.ladder.size() - 1);
  }
  if (pavement.design.elements.rim_rows != RimRows::None)
    std::printf("rim rows %s: %d of %zu rims, %d elements along them; %d pattern elements made way\n",
                std::string(enum_name(pavement.design.elements.rim_rows)).c_str(), pavement.rim_rows.loops,
                rim_row_loops(map, pavement.design.elements.rim_rows).size(), pavement.rim_rows.placed,
                pavement.rim_rows.made_way);
  const BillOfStones bill = bill_of_stones(pavement.elements, pavement.design.units);
  for (const StoneRow& row : bill.rows) {
    std::printf("stones   %ld %s of %s mm", row.count, std::string(enum_name(row.shape)).c_str(),
                diameter_mm_text(row.diameter_mm).c_str());
    // Three significant digits each, so that count x each gives the total to its last digit.
    if (row.carat_each) std::printf(", %.3g ct each, %s ct", *row.carat_each, carat_total_text(row.carat_total).c_str());
    std::printf("\n");
  }
  // Totals as stones.csv writes them (12.9195 there printed 12.919 here).
  if (bill.weighed())
    std::printf("stones   total %ld, %s ct (stones.csv)\n", bill.count, carat_total_text(bill.carat_total).c_str());
  if (pavement.design.elements.beads.enabled) {
    const nlohmann::json beads = beads_json(pavement);
    const std::size_t underheld = beads["stones_underheld"].get<std::size_t>();
    std::printf("beads    %zu shared prongs of %.2f to %.2f mm; %s held all round by at least %d (the least %d), "
                "the widest open angle around a stone %.0f degrees\n",
                beads["count"].get<std::size_t>(), beads["diameter_mm_min"].get<double>(),
                beads["diameter_mm_max"].get<double>(),
                underheld == 0 ? "every stone"
                               : (std::to_string(pavement.elements.size() - underheld) + " of " +
                                  std::to_string(pavement.elements.size()) + " stones")
                                     .c_str(),
                kBeadsPerStone, beads["holders_least"].get<int>(), beads["widest_open_deg"].get<double>());
  }
}

void print_cut(const nlohmann::json& cut, Units units) {
  if (cut.is_null()) return;
  const std::string unit(enum_name(units));
  std::printf("cut      %s cutters, metal %g %s thick: %.4g mm3 of %.4g mm3 left (%.4g removed), closed and manifold; "
              "%s triangles\n",
              cut["cutter"].get<std::string>().c_str(), cut["thickness"].get<double>(), unit.c_str(),
              cut["volume_mm3"].get<double>(), cut["shell_volume_mm3"].get<double>(),
              cut["removed_mm3"].get<double>(), std::to_string(cut["triangles"].get<std::size_t>()).c_str());
  if (cut.contains("ring")) {
    const nlohmann::json& ring = cut["ring"];
    const nlohmann::json& sizes = ring["nearest_sizes"];
    std::printf("ring     inside diameter %.2f mm (US %s, EU %s, UK %s); metal %.3g to %.3g %s thick\n",
                ring["inside_diameter_mm"].get<double>(), sizes["US"]["size"].get<std::string>().c_str(),
                sizes["EU"]["size"].get<std::string>().c_str(), sizes["UK"]["size"].get<std::string>().c_str(),
                cut["thinnest_metal"].get<double>(), cut["thickest_metal"].get<double>(), unit.c_str());
  }
  if (cut.contains("seats")) {
    const nlohmann::json& seats = cut["seats"];
    const auto figure = [](const nlohmann::json& v) { return v.is_number() ? significant_text(v.get<double>(), 3) : std::string("-"); };
    const double depth = seats.value("seat_depth", 0.0);
    const std::string set = depth > 0 ? "set " + significant_text(depth, 3) + " deep; " : "";
    std::printf("seats    %sleast metal under a culet %s, between two seats %s; tables up to %s above the surface "
                "(%s)\n",
                set.c_str(), figure(seats["least_culet_metal"]).c_str(), figure(seats["least_seat_wall"]).c_str(),
                figure(seats["highest_table"]).c_str(), unit.c_str());
  }
  std::printf("metal   ");
  for (const auto& row : cut["metal"])
    std::printf(" %s %.2f g;", row["alloy"].get<std::string>().c_str(), row["grams"].get<double>());
  std::printf("\n");
}

void print_quality(const Pavement& pavement, const PavementCounts& counts) {
  // Lengths in the surface's unit; NN over the diameter (param.png colours NN over diameter + gap).
  const std::string unit(enum_name(pavement.design.units));
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
  if (counts.face_elements > 0) std::printf(", F %.3f", final_quality.face_fill);
  if (final_quality.interior_vertex_elements > 0)
    std::printf("; regular valence: %.1f%% of %ld interior V-elements", 100 * final_quality.regular_valence_share,
                final_quality.interior_vertex_elements);
  std::printf("\n");
  const EdgeQuality& edges = final_quality.edges;
  if (edges.measured) {
    // Graded stones' spots are judged against the stone graded there (elements/bare_spots.h).
    if (pavement.grade.ladder.empty())
      std::printf("edges    %ld bare spots where a stone of %.3g %s still fits (the widest fits %.3g)", edges.bare_spots,
                  edges.spot_stone, unit.c_str(), edges.largest_fit);
    else
      std::printf("edges    %ld bare spots where %.2g of the stone graded there still fits (the widest fits %.3g %s)",
                  edges.bare_spots, kSpotStoneShare, edges.largest_fit, unit.c_str());
    if (edges.rim_samples > 0)
      std::printf("; rim metal p95 %.2f d, max %.2f d", edges.rim_metal_p95, edges.rim_metal_max);
    std::printf("\n");
  }
}

void print_times(const StageTimings& timings) {
  std::printf("time    ");
  double total = 0;
  for (const auto& [stage, ms] : timings) std::printf(" %s %.1f ms,", stage.c_str(), ms), total += ms;
  std::printf(" total %.1f ms\n", total);
}

}  // namespace

bool print_run_summary(const PipelineResult& result, const SummaryContext& context) {
  const Pavement& pavement = result.pavement;
  const bool ok = print_verdict(result, context.cut);
  std::string region;  // the parts paved, as --region named them
  for (const std::string& name : result.info.region) region += (region.empty() ? " (region " : ",") + name;
  print_surface_and_map(*result.map, context.surface + (region.empty() ? "" : region + ")"));
  print_pattern(pavement, result.counts);
  print_choices(result);
  print_optimize(pavement, context);
  print_elements(*result.map, pavement, result.counts);
  print_cut(context.cut, pavement.design.units);
  print_quality(pavement, result.counts);
  print_times(result.timings);
  std::printf("wrote    %s/{%s}\n", printable(context.out).c_str(), context.written.c_str());
  return ok;
}

}  // namespace paver::cli
