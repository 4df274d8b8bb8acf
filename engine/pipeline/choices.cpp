#include "pipeline/choices.h"

#include "core/input_error.h"
#include "core/number_text.h"
#include "core/stopwatch.h"
#include "design/design_keys.h"
#include "pattern/adaptive_pattern.h"
#include "pattern/default_spacing.h"
#include "pipeline/offset_fit.h"
#include "pipeline/pave_once.h"
#include "report/verdict.h"

#include <cstdio>
#include <string>

namespace paver {

Choice best_of(const std::vector<Candidate>& candidates, const std::atomic<bool>* stop) {
  Choice choice;
  choice.elements.assign(candidates.size(), -1);
  choice.quality.assign(candidates.size(), std::nullopt);
  std::vector<double> milliseconds(candidates.size(), 0);
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const Candidate& c = candidates[i];
    const Pavement* best = choice.kept_index >= 0 ? &choice.kept : nullptr;
    if (best && ((stop && stop->load()) || (c.worth_trying && !c.worth_trying(*best)))) continue;
    Pavement paved = c.pave(best);
    choice.elements[i] = static_cast<long>(paved.elements.size());
    choice.quality[i] = paved.after;
    for (const auto& [stage, ms] : paved.timings) milliseconds[i] += ms;
    if (!best || paves_better(paved.after, best->after)) {
      choice.kept = std::move(paved);
      choice.kept_index = static_cast<int>(i);
    }
  }
  for (std::size_t i = 0; i < candidates.size(); ++i)
    if (choice.elements[i] >= 0 && int(i) != choice.kept_index)
      choice.dropped.emplace_back(candidates[i].name + "_tried", milliseconds[i]);
  return choice;
}

PavementOptions quietly(const PavementOptions& options) {
  PavementOptions quiet = options;
  quiet.on_stage = {};
  return quiet;
}

namespace {

double stages_ms(const StageTimings& timings) {
  double ms = 0;
  for (const auto& [stage, stage_ms] : timings) ms += stage_ms;
  return ms;
}

// A choice announced and timed as one stage: the time beyond the kept pavement's own stages.
void time_choice(Pavement& kept, const char* stage, const Stopwatch& watch) {
  kept.timings.insert(kept.timings.begin(), {stage, watch.milliseconds() - stages_ms(kept.timings)});
}

// --- placement.band_rows auto: the band closed and paved both ways ---

// A way round the band, closed (its error when it cannot close) and laid out at its best shift
// across: the forecast of the elements it keeps (0 where it lays nothing or breaks the design).
struct BandWay {
  BandRows rows;
  std::optional<ClosedBand> closed;
  std::string error;
  std::size_t laid_out = 0;
};

BandWay band_way(const SurfaceMap& map, const Design& design, BandRows rows) {
  BandWay way{rows, std::nullopt, "", 0};
  try {
    way.closed = close_band_design(map, design, rows);
  } catch (const InputError& e) {
    way.error = e.what();
    return way;
  }
  try {
    const Design& closed = way.closed->design;
    const UnitCell cell = check_design_cell(closed);
    Placement placement = closed.placement;
    placement.offset = best_offset_across(map, cell, closed.elements, closed.placement, way.closed->closure.step);
    way.laid_out = laid_out_count(map, cell, closed.elements, placement);
  } catch (const InputError&) {
    way.laid_out = 0;  // this way round lays nothing (or breaks the design): the other way may not
  }
  return way;
}

// Both ways closed; a band small enough (as the offset fit's finalists, counted in laid-out
// elements) is paved both ways and the better kept: the laid-out count is only a forecast (the
// bundled bangle laid out 642 along against 620 across and kept 615 against 620). A larger one
// takes the way that lays out more. Across on a tie: it filled the bundled bands better at the
// default spacing, while one row along keeps a ring of large stones whole
// (docs/holes_and_bands.md). A way that cannot close (stones too large for three steps around)
// lays nothing; when neither can, the error is the rows across's, the way auto takes on a tie.
Pavement choose_band_rows(const SurfaceMap& map, const Design& design, const PavementOptions& options) {
  check_design_cell(design);  // the design's own errors first, at its own spacing
  refuse_spacing_larger_than_map(map, design.pattern.spacing, design.placement);
  if (options.on_stage) options.on_stage("band_rows");
  const Stopwatch watch;
  const BandWay across = band_way(map, design, BandRows::Across), along = band_way(map, design, BandRows::Along);
  if (!across.closed && !along.closed) throw InputError(across.error + "; " + along.error);
  const auto paved_with = [&](BandRows rows) {
    Design named = design;
    named.placement.band_rows = rows;
    return Candidate{std::string(enum_name(rows)),
                     [&map, named, quiet = quietly(options)](const Pavement*) { return pave_once(map, named, quiet); },
                     {}};
  };
  if (!across.closed || !along.closed)
    return pave_once(
        map,
        [&] {
          Design named = design;
          named.placement.band_rows = across.closed ? BandRows::Across : BandRows::Along;
          return named;
        }(),
        quietly(options));
  const bool both = across.laid_out > 0 && along.laid_out > 0 &&
                    double(std::max(across.laid_out, along.laid_out)) <= kOffsetFitPavedPoints;
  std::vector<Candidate> candidates;
  if (both || across.laid_out >= along.laid_out) candidates.push_back(paved_with(BandRows::Across));
  if (both || along.laid_out > across.laid_out) candidates.push_back(paved_with(BandRows::Along));
  Choice choice = best_of(candidates, options.stop);
  Pavement& kept = choice.kept;
  BandClosure& closure = *kept.band_closure;
  closure.laid_out_across = across.laid_out;
  closure.laid_out_along = along.laid_out;
  if (both && choice.elements[1] >= 0) {  // paved both ways (a stop leaves the second unpaved)
    closure.kept_across = std::size_t(choice.elements[0]);
    closure.kept_along = std::size_t(choice.elements[1]);
  }
  time_choice(kept, "band_rows", watch);
  return std::move(kept);
}

// --- placement.fit_offset: the lattice shifted within one cell ---

// After the rows are turned (the shift is over the turned lattice's cell): the shifts laid out,
// and for a pattern small enough the best few and the design's own offset paved in full (the
// optimizer moves elements and resolution removes some, so the laid-out count only forecasts the
// kept one: on the bundled torus the shift that laid out 4 more kept 9 fewer); the design's own
// offset is the first candidate, so that a fit that gains nothing moves nothing.
Pavement choose_offset(const SurfaceMap& map, Design design, const PavementOptions& options) {
  const UnitCell cell = check_design_cell(design);  // the turn below is the placement's, not the cell's
  std::optional<RowAlignment> aligned;
  if (design.placement.align != AlignAxis::None) aligned = fold_row_alignment(map, cell, design.placement);
  if (options.on_stage) options.on_stage("offset_fit");
  const Stopwatch watch;
  design.placement.fit_offset = false;  // the candidates are paved at fixed offsets
  OffsetFit fit = fit_offset(map, cell, design.elements, design.placement, options.stop);
  std::vector<OffsetCandidate*> order;
  for (OffsetCandidate& c : fit.finalists)
    if (c.shift_in_cells == glm::dvec2(0)) order.push_back(&c);
  for (OffsetCandidate& c : fit.finalists)
    if (c.shift_in_cells != glm::dvec2(0)) order.push_back(&c);
  std::vector<Candidate> candidates;
  for (const OffsetCandidate* c : order) {
    Design shifted = design;
    shifted.placement.offset = c->offset;
    candidates.push_back(
        {"offset",
         [&map, shifted, quiet = quietly(options)](const Pavement*) { return pave_once(map, shifted, quiet); },
         {}});
  }
  Pavement kept;
  if (candidates.empty()) {  // too large to pave the finalists: the shift that lays out the most
    design.placement.offset = fit.chosen.offset;
    kept = pave_once(map, design, quietly(options));
  } else {
    Choice choice = best_of(candidates, options.stop);
    for (std::size_t i = 0; i < order.size(); ++i) order[i]->kept = choice.elements[i];
    for (const OffsetCandidate& c : fit.finalists)
      if (c.shift_in_cells == glm::dvec2(0)) fit.at_design.kept = c.kept;
    fit.chosen = *order[std::size_t(choice.kept_index)];
    kept = std::move(choice.kept);
  }
  kept.offset_fit = std::move(fit);
  kept.row_alignment = aligned;
  time_choice(kept, "offset_fit", watch);
  return kept;
}

// The pavement of a design whose topology is named: its band rows and offset chosen, if auto.
Pavement pave_lattice_or_adaptive(const SurfaceMap& map, Design design, const PavementOptions& options) {
  if (design.pattern.spacing <= 0) design.pattern.spacing = default_spacing(map.mesh, design.pattern);
  const bool lattice = design.pattern.topology != Topology::Adaptive;
  // Element edits name the elements of one lattice: under them auto takes across, as before auto
  // (the studio names the way at the first edit, element_editing.cpp).
  if (lattice && map_wraps(map) && design.placement.band_rows == BandRows::Auto && design.edits.empty())
    return choose_band_rows(map, design, options);
  // Not on a band paved seamlessly (it takes its own shift across), not for an adaptive pattern
  // (grown, not laid), and not under element edits, which name the elements of the lattice at the
  // design's offset (the studio folds a fitted offset into the design at the first edit). There
  // the key stays asked, and the run says it was not used.
  if (design.placement.fit_offset && lattice && !map_wraps(map) && design.edits.empty())
    return choose_offset(map, std::move(design), options);
  return pave_once(map, std::move(design), options);
}

// --- pattern.topology auto: the lattice, or the adaptive pattern where the lattice fails ---

std::string three_significant(double value) { return significant_text(value); }

// Why a lattice pavement calls for the adaptive pattern: it tore or left bare patches (the
// verdict's own bounds), which is what a map distorting the lattice does. Empty when it did not.
std::string lattice_failure(const PavementQuality& q) {
  std::string why;
  if (pattern_is_torn(q)) why = "the lattice tore (spring deviation p95 " + three_significant(q.spring_deviation_p95) + ")";
  if (has_bare_patches(q))
    why += (why.empty() ? "the lattice left bare patches (fill " : " and left bare patches (fill ") +
           three_significant(q.fill) + ")";
  return why;
}

// The candidates: the lattice (a band's on its seamless map); where it fails, a band's lattice on
// its annulus map (rows that cross the rims at an angle keep more elements at them); where the best
// lattice still fails, the same design grown on the surface. The adaptive candidate's placement is
// the design's own: the lattice's resolved one holds its fitted offset and folded alignment (a
// band's closing rotation too), which the adaptive pattern makes and reports itself, or does not
// use; on a band it takes the design's own spacing (the annulus needs no closing).
Pavement choose_topology(const SurfaceMap& map, const Design& design, const PavementOptions& options) {
  const SurfaceMap& lattice_map = map_for_topology(map, Topology::Lattice);
  Design lattice = design;
  lattice.pattern.topology = Topology::Lattice;
  const auto failed = [](const Pavement& best) { return !lattice_failure(best.after).empty(); };
  std::optional<std::string> failure, unsupported;  // the best lattice's, as the adaptive one was weighed against
  const std::vector<Candidate> candidates = {
      {"lattice", [&](const Pavement*) { return pave_lattice_or_adaptive(lattice_map, lattice, options); }, {}},
      {"annulus", [&](const Pavement*) { return pave_lattice_or_adaptive(map, lattice, options); },
       [&](const Pavement& best) { return &lattice_map != &map && failed(best); }},
      {"adaptive",
       [&](const Pavement* best) {
         Design grown = best->design;
         grown.placement = design.placement;
         if (best->band_closure) {
           // The closure's spacing is undone, and with it the stone scales it adjusted to keep the
           // stones' size: the adaptive pattern at D with the closed band's scales made 2 mm stones
           // 1.992 mm (issue 40, "stones as ordered").
           grown.pattern.spacing = best->band_closure->spacing_before;
           if (best->band_closure->stones_kept) {
             grown.elements.vertex.scale = design.elements.vertex.scale;
             for (std::size_t k = 0; k < grown.elements.edge.size() && k < design.elements.edge.size(); ++k)
               grown.elements.edge[k].scale = design.elements.edge[k].scale;
           }
         }
         grown.pattern.topology = Topology::Adaptive;
         return pave_lattice_or_adaptive(map, std::move(grown), options);
       },
       [&](const Pavement& best) {
         failure = lattice_failure(best.after);
         unsupported = failure->empty() ? "" : adaptive_pattern_unsupported(best.design);
         return !failure->empty() && unsupported->empty();
       }},
  };
  Choice choice = best_of(candidates, options.stop);
  Pavement& kept = choice.kept;
  kept.timings.insert(kept.timings.begin(), choice.dropped.begin(), choice.dropped.end());
  if (choice.elements[2] < 0) {                           // the lattice kept, the adaptive pattern not tried
    if (!failure) failure = lattice_failure(kept.after);  // a stop came first
    kept.topology_choice = failure->empty() ? "auto: lattice (it neither tore nor left bare patches)"
                           : !unsupported
                               ? "auto: lattice (stopped)"
                               : "auto: lattice; " + *failure + ", but the adaptive pattern cannot take this design (" +
                                     *unsupported + ")";
    return std::move(kept);
  }
  const bool adaptive_better = choice.kept_index == 2;
  const PavementQuality& adaptive = *choice.quality[2];
  kept.topology_choice =
      "auto: " + std::string(adaptive_better ? "adaptive" : "lattice") + "; " + *failure + ", the adaptive pattern " +
      (adaptive_better ? "did better (fill " + three_significant(adaptive.fill) + ", " +
                             count_text(judge_pavement(adaptive).problems.size(), "problem", "problems") + ")"
                       : "did no better (fill " + three_significant(adaptive.fill) + ")");
  return std::move(kept);
}

}  // namespace

Pavement make_pavement(const SurfaceMap& map, Design design, const PavementOptions& options) {
  check_edits_topology(design);  // before any work (check_design_cell repeats it per topology)
  // A band's lattice closes on its seamless map; the adaptive pattern grows on its annulus map.
  const Topology topology = design.pattern.topology;
  if (topology != Topology::Auto)
    return pave_lattice_or_adaptive(map_for_topology(map, topology), std::move(design), options);
  // Graded stones grow their pattern (only the adaptive pattern has a spacing of its own at every
  // particle); a painted field only the lattice follows.
  const bool graded = design.elements.grade.by != GradeBy::None;
  if (graded || !design.guidance.empty()) {
    const Topology kept = graded ? Topology::Adaptive : Topology::Lattice;
    design.pattern.topology = kept;
    Pavement p = pave_lattice_or_adaptive(map_for_topology(map, kept), std::move(design), options);
    p.topology_choice = graded ? "auto: adaptive (the stones are graded, which only a grown pattern follows)"
                               : "auto: lattice (a guidance field is painted, which only the lattice follows)";
    return p;
  }
  return choose_topology(map, design, options);
}

}  // namespace paver
