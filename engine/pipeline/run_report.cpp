#include "pipeline/run_report.h"

#include "elements/beads.h"

#include "report/bill_of_stones.h"

#include "report/pavement_quality.h"
#include "report/verdict.h"

#include <nlohmann/json.hpp>

#include <algorithm>

namespace paver {

// The designer's edits of single elements (design.edits) and what became of them.
nlohmann::json edits_json(const Pavement& pavement) {
  const ElementEdits& edits = pavement.design.edits;
  const int deleted = int(edits.deleted.size());
  return {{"moved", edits.moved.size()},
          {"pinned", edits.pinned_count()},
          {"added", edits.added.size()},
          {"deleted", deleted - pavement.deletions_missed},
          {"deletions_that_found_no_element", pavement.deletions_missed}};
}

// The beads (shared prongs): how many and how large, in mm; {"enabled": false} without them.
nlohmann::json beads_json(const Pavement& pavement) {
  return bead_hold_json(pavement.elements, pavement.beads, pavement.design.elements, pavement.design.units);
}

PavementCounts count_pavement(const Pavement& pavement) {
  const Pattern& pattern = pavement.pattern;
  PavementCounts c;
  c.virtual_edges = std::count(pattern.edge_virtual.begin(), pattern.edge_virtual.end(), 1);
  c.pattern_edges = pattern.edge_count() - c.virtual_edges;
  c.boundary_crossing_edges = long(pattern.crossing_edges.size());
  c.vertex_elements = std::count(pavement.elements.kind.begin(), pavement.elements.kind.end(), ElementKind::Vertex);
  c.face_elements = std::count(pavement.elements.kind.begin(), pavement.elements.kind.end(), ElementKind::Face);
  c.edge_elements = long(pavement.elements.size()) - c.vertex_elements - c.face_elements;
  c.pattern_faces = pavement.pattern.face_count();
  c.retired_particles = std::count(pavement.retired.begin(), pavement.retired.end(), 1);
  return c;
}


namespace {

// One shift of placement.fit_offset.
nlohmann::json offset_candidate_json(const OffsetCandidate& c) {
  return {{"offset", {c.offset.x, c.offset.y}},
          {"shift_in_cells", {c.shift_in_cells.x, c.shift_in_cells.y}},
          {"laid_out", c.laid_out},
          {"kept", c.kept >= 0 ? nlohmann::json(c.kept) : nlohmann::json(nullptr)}};
}

// placement.fit_offset: the offset laid, the design's own, and the finalists paved in full.
nlohmann::json offset_fit_json(const OffsetFit& fit) {
  nlohmann::json finalists = nlohmann::json::array();
  for (const OffsetCandidate& c : fit.finalists) finalists.push_back(offset_candidate_json(c));
  return {{"chosen", offset_candidate_json(fit.chosen)},
          {"at_design_offset", offset_candidate_json(fit.at_design)},
          {"tries", fit.tries},
          {"finalists", std::move(finalists)}};
}

// How a band was paved (docs/holes_and_bands.md): seamless, with the lattice closed around it, or
// as an annulus and why. null for a surface that is not a band.
nlohmann::json band_json(const SurfaceMap& map, const Pavement& pavement) {
  if (!is_band(map)) return nullptr;
  nlohmann::json band = {{"seamless", pavement.seamless}};
  if (map.seamless) band["period"] = map.seamless->period;
  if (!pavement.seamless) band["annulus_because"] = band_annulus_reason(map, pavement);
  if (const auto& c = pavement.band_closure)
    band["closure"] = {{"spacing_before", c->spacing_before}, {"spacing", c->spacing},
                       {"lattice_steps_around", c->around},    {"step_cells", {c->step.x, c->step.y}},
                       {"rotation_deg", c->rotation_deg},       {"rows", c->rows_across ? "across" : "along"},
                       {"stones_kept", c->stones_kept},         {"text", describe_band_closure(*c)}};
  if (const auto& c = pavement.band_closure; c && c->stones_kept)
    band["closure"]["gap"] = {{"asked", c->gap_asked}, {"lattice", c->lattice_gap()}};
  if (const auto& c = pavement.band_closure; c && c->laid_out_across + c->laid_out_along > 0)
    band["closure"]["rows_auto"] = {{"laid_out_across", c->laid_out_across}, {"laid_out_along", c->laid_out_along},
                                    {"kept_across", c->kept_across},         {"kept_along", c->kept_along}};
  return band;
}

nlohmann::json surface_json(const RunInfo& info, const SurfaceMap& map) {
  const bool atlas = is_atlas(map);
  return {{"path", info.surface_path},
          {"region", info.region},
          {"vertices", atlas ? map.closed_surface_vertices : map.mesh.vertex_count()},
          {"faces", atlas ? map.closed_surface_faces : map.mesh.face_count()},
          {"boundary_vertices", atlas ? 0 : boundary_vertex_count(map.mesh)},
          {"boundary_loops", atlas ? 0 : map.mesh.boundary_loops.size()},
          {"holes", atlas ? 0 : map.mesh.hole_count()},
          {"closed", atlas},
          {"charts", chart_count(map)},
          {"seam_loops", atlas ? map.mesh.boundary_loops.size() : 0},
          {"seam_length", atlas ? 0.5 * boundary_length(map.mesh) : 0.0},
          {"cut_normal", {map.cut_normal.x, map.cut_normal.y, map.cut_normal.z}},
          {"area", surface_area(map.mesh)},
          {"curvature_min", map.curvature_min},
          {"curvature_max", map.curvature_max}};
}

nlohmann::json parameterization_json(const SurfaceMap& map) {
  const auto& q = map.parameterization.quality;
  const auto& r = map.parameterization.report;
  return {{"method", map_method_key(r)},
          {"start", map_start_key(r.start_used)},
          {"iterations", r.iterations},
          {"blocked_steps", r.blocked_steps},
          {"factorizations", r.factorizations},
          {"flipped_triangles", q.flipped_triangles},
          {"boundary_intersections", q.boundary_intersections},
          {"bijective", q.bijective()},
          {"stretch_mean", q.stretch_mean},
          {"stretch_max", q.stretch_max},
          {"area_ratio_min", q.area_ratio_min},
          {"area_ratio_max", q.area_ratio_max},
          {"area_distortion_mean", q.area_distortion_mean}};
}

nlohmann::json relaxation_json(const RelaxationReport& relaxation) {
  const DefectHealingReport& healing = relaxation.healing;
  return {{"iterations", relaxation.iterations},
          {"seeds_kept", relaxation.seeds_kept},
          {"inserted", relaxation.inserted},
          {"removed", relaxation.removed},
          {"packing_iterations", relaxation.packing_iterations},
          {"jammed_removed", relaxation.jammed},
          {"healing", {{"interior_defects_before", healing.defects_before},
                       {"interior_defects_after", healing.defects_after},
                       {"tries", healing.tries},
                       {"moved", healing.moved},
                       {"milliseconds", healing.milliseconds}}},
          {"milliseconds", relaxation.milliseconds}};
}

nlohmann::json pattern_json(const SurfaceMap& map, const Pavement& pavement, const PavementCounts& counts) {
  using nlohmann::json;
  const std::optional<RowAlignment>& aligned = pavement.row_alignment;
  return {{"cell_edges", pavement.cell.edges.size()},
          {"points", pavement.pattern.point_count()},
          {"edges", counts.pattern_edges},
          {"virtual_edges", counts.virtual_edges},
          {"boundary_crossing_edges", counts.boundary_crossing_edges},
          {"faces", counts.pattern_faces},
          {"topology", enum_name(pavement.design.pattern.topology)},
          {"topology_choice", pavement.topology_choice},
          {"band", band_json(map, pavement)},
          {"row_alignment", aligned ? json{{"axis", std::string(enum_name(aligned->axis))},
                                           {"rotation_deg", aligned->rotation_deg},
                                           {"spread_deg", aligned->spread_deg},
                                           {"axis_to_surface_deg", aligned->axis_to_surface_deg}}
                                    : json(nullptr)},
          {"offset_fit", pavement.offset_fit ? offset_fit_json(*pavement.offset_fit) : json(nullptr)},
          {"defects", pavement.pattern.defects.size()},
          {"relaxation", relaxation_json(pavement.relaxation)}};
}

nlohmann::json optimization_json(const Pavement& pavement, const PavementCounts& counts) {
  using nlohmann::json;
  const SolveReport& solve = pavement.solve;
  const CoarseStartReport& coarse = pavement.coarse_start;
  return {{"backend", solve.backend.empty() ? json(nullptr) : json(solve.backend)},
          {"iterations", solve.iterations},
          {"stop_reason", enum_name(solve.reason)},
          {"converged", solve.reason == StopReason::Converged},
          {"last_max_step", solve.last_max_step},
          {"strays_pulled_back", solve.strays_pulled_back},
          {"retired_particles", counts.retired_particles},
          {"coarse_start", {{"level_points", coarse.level_points},
                            {"level_iterations", coarse.level_iterations},
                            {"retired", coarse.retired},
                            {"milliseconds", coarse.milliseconds}}},
          {"milliseconds", solve.milliseconds}};
}

// What happened after the optimizer: resolution, refill, rim rows, edits and what was removed.
void add_after_the_solve(nlohmann::json& report, const Pavement& pavement) {
  const CollisionResolutionReport& resolution = pavement.resolution;
  report["postprocess"] = {{"filled", pavement.filled}, {"eliminated", pavement.eliminated}};
  report["collision_resolution"] = {{"rounds", resolution.rounds},
                                    {"contact_springs", resolution.contact_springs},
                                    {"solver_iterations", resolution.solver_iterations},
                                    {"retired", resolution.retired},
                                    {"pairs_left", resolution.pairs_left},
                                    {"removed", resolution.removed},
                                    {"milliseconds", resolution.milliseconds}};
  report["refill"] = {{"added", pavement.refill.added},
                      {"across_seams", pavement.refill.on_seams},
                      {"waves", pavement.refill.waves},
                      {"milliseconds", pavement.refill.milliseconds}};
  report["bare_spots_closed"] = {{"added", pavement.spots_closed.added},
                                 {"pushed_in", pavement.spots_closed.pushed},
                                 {"of_edge_size", pavement.spots_closed.of_edge_size},
                                 {"rounds", pavement.spots_closed.rounds},
                                 {"too_many_stones", pavement.spots_closed.too_many_stones},
                                 {"milliseconds", pavement.spots_closed.milliseconds}};
  nlohmann::json sizes = nlohmann::json::array();
  for (const SizeFill::Size& size : pavement.size_fill.sizes)
    sizes.push_back({{"diameter", size.diameter}, {"added", size.added}});
  report["fill_sizes"] = {{"sizes", sizes},
                          {"added", pavement.size_fill.added()},
                          {"searches", pavement.size_fill.rounds},
                          {"milliseconds", pavement.size_fill.milliseconds}};
  if (pavement.design.elements.grade.by != GradeBy::None) {
    const double mm = millimetres_per_unit(pavement.design.units);
    nlohmann::json ladder = nlohmann::json::array();
    for (const double d : pavement.grade.ladder) ladder.push_back(d * mm);
    report["grade"] = {{"by", std::string(enum_name(pavement.design.elements.grade.by))},
                       {"ladder_mm", ladder},
                       {"graded", pavement.grade.graded}};
  }
  report["rim_rows"] = {{"rims", std::string(enum_name(pavement.design.elements.rim_rows))},
                        {"loops", pavement.rim_rows.loops},
                        {"placed", pavement.rim_rows.placed},
                        {"made_way", pavement.rim_rows.made_way}};
  report["edits"] = edits_json(pavement);
  report["removed"] = {{"total", pavement.eliminated + resolution.removed + pavement.rim_rows.made_way},
                       {"crossing_the_boundary", pavement.eliminated},
                       {"still_colliding_after_resolution", resolution.removed},
                       {"making_way_for_rim_rows", pavement.rim_rows.made_way}};
}

}  // namespace

nlohmann::json make_run_report(const RunInfo& info, const SurfaceMap& map, const Pavement& pavement,
                               const StageTimings& timings) {
  using nlohmann::json;
  const PavementCounts counts = count_pavement(pavement);
  json timing = json::object();
  double total = 0;
  for (const auto& [stage, ms] : timings) timing[stage] = ms, total += ms;
  timing["total"] = total;
  const Design& design = pavement.design;
  json report = {
      {"paver_report_version", 1},
      {"surface", surface_json(info, map)},
      {"parameterization", parameterization_json(map)},
      {"design", {{"source", info.design_source},
                  {"units", enum_name(design.units)},
                  {"tessellation", enum_name(design.pattern.tessellation)},
                  {"spacing", design.pattern.spacing},
                  {"gap", design.elements.gap},
                  {"margin", design.elements.margin},
                  {"spacing_derived", info.spacing_derived}}},
      {"pattern", pattern_json(map, pavement, counts)},
      {"elements", {{"total", pavement.elements.size()},
                    {"vertex", counts.vertex_elements},
                    {"edge", counts.edge_elements},
                    {"face", counts.face_elements}}},
      {"optimization", optimization_json(pavement, counts)},
  };
  add_after_the_solve(report, pavement);
  report["verdict"] = to_json(judge_pavement(pavement.after));
  report["stones"] = to_json(bill_of_stones(pavement.elements, design.units));
  report["beads"] = beads_json(pavement);
  report["quality_before"] = to_json(pavement.before);
  report["quality_paper_method"] = to_json(pavement.paper);
  report["quality_after"] = to_json(pavement.after);
  report["timings_ms"] = timing;
  return report;
}

}  // namespace paver
