#include "pipeline/pavement.h"

#include "core/number_text.h"
#include "core/stopwatch.h"
#include "elements/beads.h"
#include "elements/boundary_postprocess.h"
#include "pattern/adaptive_pattern.h"
#include "solver/edit_relaxation.h"
#include "solver/guidance_field.h"
#include "solver/surface_spring_relaxation.h"
#include "pattern/default_spacing.h"
#include "pattern/design_overlap.h"
#include "elements/element_placement.h"
#include "elements/element_deletion.h"
#include "elements/element_ids.h"
#include "pattern/pattern_edits.h"
#include "pipeline/offset_fit.h"
#include "core/input_error.h"
#include "report/verdict.h"

#include <glm/geometric.hpp>

#include <array>
#include <cmath>
#include <limits>
#include <cstdio>
#include <string>

namespace paver {
UnitCell make_design_cell(const PatternDesign& pattern) {
  UnitCell cell = make_unit_cell(pattern.tessellation, pattern.spacing);
  for (size_t i = 0; i < pattern.operators.size(); ++i) {
    try {
      apply_operator(cell, pattern.operators[i]);
    } catch (const InputError& e) {
      throw DesignError("pattern.operators[" + std::to_string(i) + "]: " + e.what());
    }
  }
  if (pattern.bracing) add_bracing_edges(cell);
  return cell;
}

PlacedElements place_all_elements(const SurfaceMap& map, const Pattern& pattern, const std::vector<glm::dvec2>& points,
                                  const Design& design, bool postprocess, const std::vector<std::uint8_t>* retired) {
  PlacedElements placed;
  const EdgeAnchor anchor =
      design.pattern.topology == Topology::Adaptive ? EdgeAnchor::SurfaceChord : EdgeAnchor::MapLine;
  placed.elements = place_elements(map, pattern, points, design.elements, design.pattern.spacing, retired, anchor);
  if (postprocess) {
    placed.filled = fill_boundary_edges(map, pattern, points, design.elements, design.pattern.spacing, placed.elements,
                                        retired);
    placed.eliminated = eliminate_boundary_elements(
        map, placed.elements, boundary_margin(map, design.elements.margin, design.elements.gap));
  }
  return placed;
}

namespace {
// Element ids name the elements of one pattern, and only the lattice's solver holds particles or
// follows a painted field.
void check_edits_topology(const Design& design) {
  const Topology topology = design.pattern.topology;
  if (!design.guidance.empty() && topology == Topology::Adaptive)
    throw DesignError("guidance: the adaptive pattern cannot follow a guidance field yet; use pattern.topology "
                     "\"lattice\" (or \"auto\", which keeps the lattice when a field is painted)");
  const ElementEdits& edits = design.edits;
  if (edits.empty()) return;
  if (topology == Topology::Auto)
    throw DesignError("edits: element edits name the elements of one pattern, but pattern.topology is \"auto\"; "
                     "set it to \"lattice\" or \"adaptive\" (the one the edits were made on)");
  if (topology == Topology::Adaptive && !(edits.moved.empty() && edits.added.empty()))
    throw DesignError(std::string("edits.") + (edits.moved.empty() ? "added" : "moved") +
                     ": the adaptive pattern's relaxation cannot hold elements in place yet; use pattern.topology "
                     "\"lattice\" to pin, move or add elements (deleting works on both)");
}

}  // namespace

UnitCell check_design_cell(const Design& design) {
  check_edits_topology(design);
  // The checks run on the cell at D = 1: they are scale-free, and a spacing far from the surface's
  // size (or still 0, to be derived) must not make lengths underflow into false overlaps.
  PatternDesign unit = design.pattern;
  unit.spacing = 1;
  const UnitCell unit_cell = make_design_cell(unit);
  for (size_t s = 0; s < design.elements.edge.size(); ++s)
    for (int e : design.elements.edge[s].cell_edges)
      if (e < 0 || e >= int(unit_cell.edges.size()))
        throw DesignError("elements.edge[" + std::to_string(s) + "].cell_edges: edge " + std::to_string(e) +
                         " does not exist; the unit cell has edges 0.." + std::to_string(unit_cell.edges.size() - 1));
  if (!design.elements.allow_overlap) check_design_overlaps(unit_cell, design.elements, 1.0);
  if (design.pattern.topology == Topology::Adaptive)
    if (const std::string why = adaptive_pattern_unsupported(design); !why.empty())
      throw DesignError("pattern.topology: \"adaptive\" cannot take this design: " + why +
                       "; use \"lattice\"");
  if (design.pattern.spacing <= 0) return unit_cell;
  UnitCell cell = design.pattern.spacing != 1 ? make_design_cell(design.pattern) : unit_cell;
  // The gap is in surface units: it is checked at the real spacing, once that is known.
  if (!design.elements.allow_overlap && design.elements.gap > 0)
    check_design_overlaps(cell, design.elements, design.pattern.spacing, design.elements.gap);
  return cell;
}

namespace {

Pavement pave_with_topology(const SurfaceMap& map, Design design, const PavementOptions& options);

// A band closed with its rows one way: the design at the closed D and the band's rotation (its
// rows resolved), and, when found, the shift across the band that lays out the most.
struct ClosedBand {
  Design design;
  BandClosure closure;
  std::optional<glm::dvec2> offset;
};

ClosedBand closed_band(const SurfaceMap& map, Design design, BandRows rows) {
  design.placement.band_rows = rows;
  // Stones (gem elements) come in catalogue sizes: they keep their diameter, the gap takes the
  // change, and so D may only grow. Other elements are sized with D, as everywhere.
  const bool stones = keeps_stone_sizes(design.elements);
  BandClosure closure = close_band(map, make_design_cell(design.pattern), design.placement, stones);
  if (stones) {
    keep_stone_sizes(design.elements, closure.spacing_before, closure.spacing);
    closure.stones_kept = true;
  } else if (closure.spacing < design.pattern.spacing) {
    // Closer elements may break the design's gap, which is in surface units: then one step fewer.
    Design closer = design;
    closer.pattern.spacing = closure.spacing;
    try {
      check_design_cell(closer);
    } catch (const InputError&) {
      closure = close_band(map, make_design_cell(design.pattern), design.placement, true);
    }
  }
  design.pattern.spacing = closure.spacing;
  design.placement.rotation_deg = closure.rotation_deg;
  return {std::move(design), closure, std::nullopt};
}

// band_rows auto: the band closed both ways, each at its best shift across. A band small enough
// (as the offset fit's finalists, counted in laid-out elements) is paved both ways, quietly, and
// the better kept (paves_better: fewer verdict problems, then the higher fill): the laid-out count
// is only a forecast (the bundled bangle laid out 642 along against 620 across and kept 615
// against 620). A larger one takes the way that lays out more. Across on a tie: it filled the
// bundled bands better at the default spacing, while one row along keeps a ring of large stones
// whole (docs/holes_and_bands.md). Each quiet pavement closes the band and searches its shift
// again (16 layouts each): bounded by the size limit, and simpler than passing them in.
ClosedBand closed_band_with_more_elements(const SurfaceMap& map, const Design& design, const PavementOptions& options) {
  const auto laid_out = [&](ClosedBand& band) -> std::size_t {
    try {
      const UnitCell cell = check_design_cell(band.design);
      band.offset = best_offset_across(map, cell, band.design, band.closure.step);
      Placement placement = band.design.placement;
      placement.offset = *band.offset;
      return laid_out_count(map, cell, band.design, placement);
    } catch (const InputError&) {
      band.offset.reset();  // this way round lays nothing (or breaks the design): the other way may not
      return 0;
    }
  };
  // A way that cannot close (stones too large for three steps around) lays nothing; when neither
  // can, the error is the rows across's, the way auto takes on a tie.
  const auto closed_or_none = [&](BandRows rows, std::string& error) -> std::optional<ClosedBand> {
    try {
      return closed_band(map, design, rows);
    } catch (const InputError& e) {
      error = e.what();
      return std::nullopt;
    }
  };
  std::string across_error, along_error;
  std::optional<ClosedBand> across_closed = closed_or_none(BandRows::Across, across_error);
  std::optional<ClosedBand> along_closed = closed_or_none(BandRows::Along, along_error);
  if (!across_closed && !along_closed) throw InputError(across_error + "; " + along_error);
  if (!across_closed || !along_closed) return std::move(across_closed ? *across_closed : *along_closed);
  ClosedBand& across = *across_closed;
  ClosedBand& along = *along_closed;
  const std::size_t across_count = laid_out(across), along_count = laid_out(along);
  bool take_along = along_count > across_count;
  std::size_t across_kept = 0, along_kept = 0;
  if (across_count > 0 && along_count > 0 && double(std::max(across_count, along_count)) <= kOffsetFitPavedPoints &&
      !(options.stop && options.stop->load())) {
    PavementOptions quiet = options;
    quiet.on_stage = {};
    quiet.observer = {};
    quiet.on_pattern = {};
    const auto paved = [&](const ClosedBand& band) {
      Design named = design;
      named.placement.band_rows = band.design.placement.band_rows;
      return pave_with_topology(map, std::move(named), quiet);
    };
    const Pavement by_across = paved(across);
    if (!(options.stop && options.stop->load())) {  // else the caller ends the run
      const Pavement by_along = paved(along);
      across_kept = by_across.elements.size();
      along_kept = by_along.elements.size();
      take_along = paves_better(by_along.after, by_across.after);
    }
  }
  ClosedBand& kept = take_along ? along : across;
  kept.closure.laid_out_across = across_count;
  kept.closure.laid_out_along = along_count;
  kept.closure.kept_across = across_kept;
  kept.closure.kept_along = along_kept;
  return std::move(kept);
}

// The laid-out count only forecasts the kept one: the optimizer moves elements and resolution
// removes some (on the bundled torus, the shift that laid out 4 more kept 9 fewer). So the
// finalists are paved in full, quietly (no stage names, observer or pattern hook: the chosen one is
// paved again with them), and choose_finalist picks the one to lay.
void pave_finalists(const SurfaceMap& map, const Design& design, const PavementOptions& options, OffsetFit& fit) {
  if (fit.finalists.empty()) return;
  PavementOptions quiet = options;
  quiet.on_stage = {};
  quiet.observer = {};
  quiet.on_pattern = {};
  std::vector<bool> ok;
  for (OffsetCandidate& c : fit.finalists) {
    if (options.stop && options.stop->load()) return;  // the caller ends the run
    Design shifted = design;
    shifted.placement.offset = c.offset;
    const Pavement paved = pave_with_topology(map, std::move(shifted), quiet);
    c.kept = static_cast<long>(paved.elements.size());
    if (c.shift_in_cells == glm::dvec2(0)) fit.at_design.kept = c.kept;
    ok.push_back(judge_pavement(paved.after).ok);
  }
  fit.chosen = fit.finalists[choose_finalist(fit.finalists, ok)];
}

// The pavement of one topology (lattice or adaptive).
Pavement pave_with_topology(const SurfaceMap& map, Design design, const PavementOptions& options) {
  Pavement pavement;
  // Each stage's clock starts where the caller hears that it starts.
  const auto start = [&](const char* stage) {
    if (options.on_stage) options.on_stage(stage);
    return Stopwatch();
  };
  Stopwatch watch = start("pattern");
  double pattern_ms = 0;
  if (design.pattern.spacing <= 0)
    design.pattern.spacing = default_spacing(map.mesh, design.pattern.tessellation);
  const bool adaptive = design.pattern.topology == Topology::Adaptive;
  std::optional<glm::dvec2> band_offset;  // the shift across the band, when auto rows found it
  if (map_wraps(map) && !adaptive) {
    // A band's seamless map: the lattice turned and its D changed a little, so that it closes.
    check_design_cell(design);  // the design's own errors first, at its own spacing
    refuse_spacing_larger_than_map(map, design.pattern.spacing, design.placement);
    // Element edits name the elements of one lattice: under them auto takes across, as before auto
    // (the studio names the way at the first edit, element_editing.cpp).
    const bool choose_rows = design.placement.band_rows == BandRows::Auto && design.edits.empty();
    const BandRows named_rows = design.placement.band_rows == BandRows::Along ? BandRows::Along : BandRows::Across;
    ClosedBand closed;
    if (choose_rows) {
      pattern_ms += watch.milliseconds();  // the choice is timed on its own
      watch = start("band_rows");
      closed = closed_band_with_more_elements(map, design, options);
      pavement.timings.emplace_back("band_rows", watch.milliseconds());
      watch = Stopwatch();  // the pattern stage goes on (its name was said)
    } else {
      closed = closed_band(map, design, named_rows);
    }
    design = std::move(closed.design);
    band_offset = closed.offset;
    pavement.band_closure = closed.closure;
    pavement.seamless = true;
  }
  pavement.cell = check_design_cell(design);
  if (design.placement.align != AlignAxis::None && !pavement.seamless) {
    const std::optional<RowAlignment> aligned = align_rows(map, pavement.cell, design.placement.align);
    if (!aligned)
      throw DesignError("placement.align: the " + std::string(enum_name(design.placement.align)) +
                        " axis is normal to the surface almost everywhere, so rows cannot follow it; use another "
                        "axis or none");
    design.placement.rotation_deg += aligned->rotation_deg;
    design.placement.align = AlignAxis::None;
    pavement.row_alignment = aligned;
  }
  // After the rows are turned: the shift is over the turned lattice's cell. Not on a band paved
  // seamlessly (it takes its own shift across, below), not for an adaptive pattern (grown, not
  // laid), and not under element edits, which name the elements of the lattice at the design's
  // offset (the studio folds a fitted offset into the design at the first edit). There the key
  // stays asked, and the run says it was not used.
  if (design.placement.fit_offset && !pavement.seamless && !adaptive && design.edits.empty()) {
    pattern_ms += watch.milliseconds();  // the fit is timed on its own
    watch = start("offset_fit");
    design.placement.fit_offset = false;  // the finalists are paved at fixed offsets
    OffsetFit fit = fit_offset(map, pavement.cell, design, options.stop);
    pave_finalists(map, design, options, fit);
    design.placement.offset = fit.chosen.offset;
    pavement.offset_fit = std::move(fit);
    pavement.timings.emplace_back("offset_fit", watch.milliseconds());
    watch = Stopwatch();  // the pattern stage goes on (its name was said)
  }
  if (pavement.seamless)
    design.placement.offset =
        band_offset ? *band_offset : best_offset_across(map, pavement.cell, design, pavement.band_closure->step);
  const QualityBasis basis = quality_basis(map, pavement.cell, design.elements, design.solver, design.guidance);
  // The adaptive pattern is grown instead of the lattice (docs/topology.md).
  if (adaptive) {
    AdaptivePattern grown = build_adaptive_pattern(map, pavement.cell, design, options.stop);
    pavement.pattern = std::move(grown.pattern);
    pavement.relaxation = grown.relaxation;
  } else {
    pavement.pattern = build_pattern(map, pavement.cell, design.placement);
  }
  const std::vector<EditedParticle> edited =
      add_edited_points(map, pavement.pattern, design.edits, design.elements.vertex.scale * design.pattern.spacing,
                        design.elements.gap);
  pavement.points = pavement.pattern.points;
  pavement.timings.emplace_back("pattern", pattern_ms + watch.milliseconds());
  // Before any element is placed or measured: the caller's bounds (run_pipeline's output size)
  // refuse a design here at the cost of its pattern alone.
  if (options.on_pattern) options.on_pattern(pavement.pattern, design);

  watch = start("measure_initial");
  const PlacedElements initial = place_all_elements(map, pavement.pattern, pavement.points, design, options.postprocess);
  pavement.before =
      measure_pavement(map, pavement.pattern, pavement.points, initial.elements, basis, nullptr, Measure::Counts);
  pavement.timings.emplace_back("measure_initial", watch.milliseconds());

  pavement.retired.assign(pavement.points.size(), 0);
  const auto place = [&](const std::vector<glm::dvec2>& points, const std::vector<std::uint32_t>& stray_count) {
    for (size_t i = 0; i < stray_count.size(); ++i) pavement.retired[i] = stray_count[i] == kRetired ? 1 : 0;
    PlacedElements placed =
        place_all_elements(map, pavement.pattern, points, design, options.postprocess, &pavement.retired);
    pavement.filled = placed.filled;
    pavement.eliminated = placed.eliminated;
    return std::move(placed.elements);
  };
  if (options.optimize && adaptive && pavement.pattern.point_count() > 0) {
    // The adaptive pattern's own optimizer, on the surface, with contact in it; removal is the
    // last resort for what still collides.
    watch = start("optimize");
    pavement.solve = relax_pattern_on_surface(map, pavement.pattern, pavement.points, design, {}, options.stop);
    pavement.solve.backend = "cpu";  // the adaptive pattern's optimizer has no GPU path
    pavement.timings.emplace_back("optimize", watch.milliseconds());
    watch = start("measure_paper");
    pavement.elements = place(pavement.points, {});
    pavement.paper = measure_pavement(map, pavement.pattern, pavement.points, pavement.elements, basis,
                                      &pavement.retired, Measure::Counts);
    pavement.timings.emplace_back("measure_paper", watch.milliseconds());
    if (options.resolve_collisions && !design.elements.allow_overlap) {
      watch = start("resolve_collisions");
      const Removal removal = remove_colliding(pavement.elements, design.elements.gap);
      pavement.resolution.pairs_left = removal.pairs;
      pavement.resolution.removed = removal.removed;
      pavement.timings.emplace_back("resolve_collisions", watch.milliseconds());
    }
  } else if (options.optimize && pavement.pattern.point_count() > 0) {
    watch = start("optimize");
    const SolverSurface surface = make_solver_surface(map);
    SpringSystem system = make_spring_system(pavement.pattern);
    apply_guidance(system, pavement.pattern, design.guidance);
    set_aside_added(system, edited);
    const SolverFactory factory = options.solver ? options.solver : cpu_solver_factory(options.threads);
    const PatternAtSpacing pattern_at = [&](double spacing) {
      PatternDesign coarser = design.pattern;
      coarser.spacing = spacing;
      return build_pattern(map, make_design_cell(coarser), design.placement);
    };
    // An atlas's charts lie side by side in one uv frame: a field over it would blend them.
    if (!is_atlas(map))
      pavement.coarse_start =
          coarse_start(surface, system, pattern_at, design.solver, design.pattern.spacing, factory, options.stop);
    const std::unique_ptr<SpringSolverBackend> solver = factory(surface, system, design.solver, design.pattern.spacing);
    pavement.solve = solver->solve(options.observer, options.stop);
    pavement.solve.backend = std::string(solver->backend_name());
    pavement.timings.emplace_back("optimize", watch.milliseconds());
    for (int i = 0; i < system.particle_count(); ++i) pavement.points[i] = glm::dvec2(system.position[i]);

    watch = start("measure_paper");
    pavement.elements = place(pavement.points, system.stray_count);
    pavement.paper = measure_pavement(map, pavement.pattern, pavement.points, pavement.elements, basis,
                                      &pavement.retired, Measure::Counts);
    pavement.timings.emplace_back("measure_paper", watch.milliseconds());
    // Designs that overlap on purpose keep their overlaps.
    if (options.resolve_collisions && !design.elements.allow_overlap) {
      watch = start("resolve_collisions");
      pavement.elements = resolve_collisions(map, surface, system, pavement.pattern, design, pavement.points, place,
                                             factory, options.resolution, pavement.resolution, options.stop);
      pavement.timings.emplace_back("resolve_collisions", watch.milliseconds());
    }
    if (!edited.empty()) {
      // The edits start from the design's own pavement and change it only around them.
      watch = start("edits");
      const HeldParticles beyond = place_edits(system, edited, design.pattern.spacing);
      for (int i = 0; i < system.particle_count(); ++i) pavement.points[i] = glm::dvec2(system.position[i]);
      if (options.resolve_collisions && !design.elements.allow_overlap) {
        CollisionResolutionReport around;
        // An edit's few collisions are the designer's: pushed apart in every round, never left
        // to the last resort early, whatever the pattern's size.
        CollisionResolutionOptions every_round = options.resolution;
        every_round.large_pattern_particles = std::numeric_limits<int>::max();
        pavement.elements = resolve_collisions(map, surface, system, pavement.pattern, design, pavement.points, place,
                                               factory, every_round, around, options.stop);
        pavement.resolution.rounds += around.rounds;
        pavement.resolution.contact_springs += around.contact_springs;
        pavement.resolution.solver_iterations += around.solver_iterations;
        pavement.resolution.retired += around.retired;
        pavement.resolution.removed = around.removed;  // the final elements are this resolution's
      } else {
        pavement.elements = place(pavement.points, system.stray_count);
      }
      release_held(system, beyond);
      pavement.timings.emplace_back("edits", watch.milliseconds());
    }
  } else {
    for (const EditedParticle& e : edited) pavement.points[std::size_t(e.particle)] = e.to;  // unoptimized: as put
    pavement.elements = place(pavement.points, {});
    pavement.paper = pavement.before;
  }
  if (design.elements.rim_rows != RimRows::None && !design.elements.allow_overlap) {
    watch = start("rim_rows");
    pavement.rim_rows = place_rim_rows(map, pavement.elements, design);
    pavement.timings.emplace_back("rim_rows", watch.milliseconds());
  }
  if (options.refill && !design.elements.allow_overlap) {
    watch = start("refill");
    // Across a closed surface's seams first, so that the bare regions' refill grows from there too.
    RefillReport seams;
    // The refill adds V-elements: at the V-elements' own density, not all elements' (a honeycomb
    // with edge elements has room in every hexagon at the mixed density).
    const double area_per_vertex_element =
        basis.vertex_share > 0 ? basis.area_per_element / basis.vertex_share : basis.area_per_element;
    refill_seams(map, pavement.elements, design, area_per_vertex_element, seams);
    pavement.refill = refill_bare_regions(map, pavement.elements, design, area_per_vertex_element, options.stop);
    pavement.refill.added += seams.added;
    pavement.refill.on_seams = seams.on_seams;
    pavement.refill.milliseconds += seams.milliseconds;
    pavement.timings.emplace_back("refill", watch.milliseconds());
  }

  number_elements(pavement.elements, pavement.pattern, design.edits.added);
  if (!design.edits.deleted.empty()) {
    watch = start("deletions");
    pavement.deletions_missed =
        delete_elements(pavement.elements, design.edits, first_refill_id(pavement.pattern));
    pavement.timings.emplace_back("deletions", watch.milliseconds());
  }

  watch = start("measure");
  pavement.after =
      measure_pavement(map, pavement.pattern, pavement.points, pavement.elements, basis, &pavement.retired);
  pavement.timings.emplace_back("measure", watch.milliseconds());
  if (design.elements.beads.enabled) {
    watch = start("beads");
    pavement.beads = place_beads(map, pavement.elements, design.elements);
    number_beads(pavement.beads, pavement.elements);
    pavement.timings.emplace_back("beads", watch.milliseconds());
  }
  pavement.design = std::move(design);
  return pavement;
}

std::string three_digits(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

// Why a lattice pavement calls for the adaptive pattern: it tore or left bare patches (the
// verdict's own bounds), which is what a map distorting the lattice does. Empty when it did not.
std::string lattice_failure(const PavementQuality& q) {
  std::string why;
  if (pattern_is_torn(q))
    why = "the lattice tore (spring deviation p95 " + three_digits(q.spring_deviation_p95) + ")";
  if (has_bare_patches(q))
    why += (why.empty() ? "the lattice left bare patches (fill " : " and left bare patches (fill ") +
           three_digits(q.fill) + ")";
  return why;
}

}  // namespace

const Elements& stones_and_beads(const Pavement& pavement, Elements& storage,
                                 std::vector<std::array<std::uint8_t, 3>>* colours) {
  if (pavement.beads.size() == 0) return pavement.elements;
  storage = pavement.elements;
  storage.append(pavement.beads);
  if (colours) colours->resize(storage.size(), kind_colour(ElementKind::Bead));
  return storage;
}

const SurfaceMap& map_for_topology(const SurfaceMap& map, Topology topology) {
  return map.seamless && topology != Topology::Adaptive ? *map.seamless : map;
}

std::string band_annulus_reason(const SurfaceMap& map, const Pavement& pavement) {
  if (!is_band(map) || pavement.seamless) return "";
  if (!map.seamless_unavailable.empty()) return map.seamless_unavailable;
  return pavement.design.pattern.topology == Topology::Lattice
             ? "the seamless lattice tore or left bare patches; the lattice on the annulus did better"
             : "the adaptive pattern grows on the annulus map";
}

const SurfaceMap& pavement_map(const SurfaceMap& map, const Pavement& pavement) {
  return pavement.seamless && map.seamless ? *map.seamless : map;
}

Pavement make_pavement(const SurfaceMap& map, Design design, const PavementOptions& options) {
  check_edits_topology(design);  // before any work (check_design_cell repeats it per topology)
  // A band's lattice closes on its seamless map; the adaptive pattern grows on its annulus map.
  const SurfaceMap& lattice_map = map_for_topology(map, Topology::Lattice);
  if (design.pattern.topology == Topology::Lattice) return pave_with_topology(lattice_map, std::move(design), options);
  if (design.pattern.topology == Topology::Adaptive) return pave_with_topology(map, std::move(design), options);
  if (!design.guidance.empty()) {  // only the lattice follows a painted field
    design.pattern.topology = Topology::Lattice;
    Pavement p = pave_with_topology(lattice_map, std::move(design), options);
    p.topology_choice = "auto: lattice (a guidance field is painted, which only the lattice follows)";
    return p;
  }
  Design lattice = design;
  lattice.pattern.topology = Topology::Lattice;
  Pavement first = pave_with_topology(lattice_map, lattice, options);
  bool stopped = options.stop && options.stop->load();
  if (&lattice_map != &map && !lattice_failure(first.after).empty() && !stopped) {
    // A band whose seamless lattice tore or left bare patches: the lattice on its annulus map too
    // (rows that cross the rims at an angle keep more elements at them); the better one is kept.
    Pavement annulus = pave_with_topology(map, std::move(lattice), options);
    const bool annulus_better = paves_better(annulus.after, first.after);
    Pavement& kept = annulus_better ? annulus : first;
    const Pavement& dropped = annulus_better ? first : annulus;
    double tried = 0;
    for (const auto& [stage, ms] : dropped.timings) tried += ms;
    kept.timings.insert(kept.timings.begin(), {annulus_better ? "seamless_tried" : "annulus_tried", tried});
    if (annulus_better) first = std::move(annulus);
    stopped = options.stop && options.stop->load();
  }
  const std::string failure = lattice_failure(first.after);
  const std::string unsupported = failure.empty() ? "" : adaptive_pattern_unsupported(first.design);
  if (failure.empty() || stopped || !unsupported.empty()) {
    first.topology_choice = failure.empty() ? "auto: lattice (it neither tore nor left bare patches)"
                            : stopped       ? "auto: lattice (stopped)"
                                            : "auto: lattice; " + failure +
                                                  ", but the adaptive pattern cannot take this design (" + unsupported + ")";
    return first;
  }
  // The same design, spacing as resolved, grown on the surface; kept when it judges better. Its
  // placement is the design's own: the lattice's resolved one holds the lattice's fitted offset
  // and folded alignment (a band's closing rotation too), which the adaptive pattern makes and
  // reports itself, or does not use.
  Design grown = first.design;
  grown.placement = design.placement;
  if (first.band_closure)  // the annulus needs no closing: the design's own spacing
    grown.pattern.spacing = first.band_closure->spacing_before;
  grown.pattern.topology = Topology::Adaptive;
  Pavement second = pave_with_topology(map, std::move(grown), options);
  const Verdict lattice_verdict = judge_pavement(first.after), adaptive_verdict = judge_pavement(second.after);
  const bool adaptive_better = paves_better(second.after, first.after);
  Pavement& kept = adaptive_better ? second : first;
  const Pavement& dropped = adaptive_better ? first : second;
  kept.topology_choice = "auto: " + std::string(adaptive_better ? "adaptive" : "lattice") + "; " + failure +
                         ", the adaptive pattern " +
                         (adaptive_better ? "did better (fill " + three_digits(second.after.fill) + ", " +
                                                count_text(adaptive_verdict.problems.size(), "problem", "problems") + ")"
                                          : "did no better (fill " + three_digits(second.after.fill) + ")");
  double tried = 0;
  for (const auto& [stage, ms] : dropped.timings) tried += ms;
  kept.timings.insert(kept.timings.begin(), {adaptive_better ? "lattice_tried" : "adaptive_tried", tried});
  return std::move(kept);
}

}  // namespace paver
