#include "pipeline/pave_once.h"

#include "core/input_error.h"
#include "core/stopwatch.h"
#include "design/design_keys.h"
#include "elements/beads.h"
#include "elements/boundary_postprocess.h"
#include "elements/element_deletion.h"
#include "elements/element_ids.h"
#include "elements/stone_grade.h"
#include "pattern/adaptive_pattern.h"
#include "pattern/band_closure.h"
#include "pattern/default_spacing.h"
#include "pattern/design_cell.h"
#include "pattern/pattern_edits.h"
#include "pipeline/offset_fit.h"
#include "report/verdict.h"
#include "solver/edit_relaxation.h"
#include "solver/guidance_field.h"
#include "solver/surface_spring_relaxation.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>

namespace paver {

Elements PaveState::place(const PaveContext& context, const std::vector<glm::dvec2>& points,
                          const std::vector<std::uint32_t>& stray_count) {
  for (size_t i = 0; i < stray_count.size(); ++i) pavement.retired[i] = stray_count[i] == kRetired ? 1 : 0;
  PlacedElements placed =
      place_all_elements(context.map, pavement.pattern, points, design.elements, design.pattern.spacing,
                         edge_anchor(design.pattern.topology), context.options.postprocess, &pavement.retired,
                         grade.get());
  pavement.filled = placed.filled;
  pavement.eliminated = placed.eliminated;
  return std::move(placed.elements);
}

namespace {

// --- the pattern: the band closed, the rows turned, the lattice laid (or the pattern grown) ---

// A band's seamless map: the lattice turned and its D changed a little, so that it closes.
void close_the_band(const PaveContext& c, PaveState& s) {
  check_design_cell(s.design);  // the design's own errors first, at its own spacing
  refuse_spacing_larger_than_map(c.map, s.design.pattern.spacing, s.design.placement);
  const BandRows rows = s.design.placement.band_rows == BandRows::Along ? BandRows::Along : BandRows::Across;
  ClosedBand closed = close_band_design(c.map, std::move(s.design), rows);
  s.design = std::move(closed.design);
  s.pavement.band_closure = closed.closure;
  s.pavement.seamless = true;
}

void lay_out_pattern(const PaveContext& c, PaveState& s) {
  Design& design = s.design;
  Pavement& pavement = s.pavement;
  if (design.pattern.spacing <= 0) design.pattern.spacing = default_spacing(c.map.mesh, design.pattern);
  if (map_wraps(c.map) && !s.adaptive()) close_the_band(c, s);
  pavement.cell = check_design_cell(design);
  if (design.placement.align != AlignAxis::None && !pavement.seamless)
    pavement.row_alignment = fold_row_alignment(c.map, pavement.cell, design.placement);
  if (pavement.seamless)
    design.placement.offset =
        best_offset_across(c.map, pavement.cell, design.elements, design.placement, pavement.band_closure->step);
  s.grade = make_grade_field(c.map, design);
  if (s.grade) pavement.grade.ladder = s.grade->ladder();
  s.basis = quality_basis(c.map, pavement.cell, design.elements, design.solver, design.guidance, s.grade);
  // Auto rim rows: every rim for pave as the edges judge it (report/edge_quality.h), but for a band
  // whose lattice rows run along its rims already (closed with rows along): there the rows of the
  // pattern are the rim rows, and rows laid over them fought them (a ring of 12 large stones kept 7).
  // The adaptive pattern grows against the rims already (packed to the margin): rows laid over it
  // made way for 4 and left 15 spots on a narrow band. The rims measured are the rows' then. A
  // closed surface has seams, no rims: none (its summary said "rim rows all: 0 of 0 rims").
  const bool rows_along_rims = pavement.band_closure && !pavement.band_closure->rows_across;
  const bool has_rims = !is_atlas(c.map) && !c.map.mesh.boundary_loops.empty();
  design.elements.rim_rows = concrete_rim_rows(design.elements.rim_rows,
                                               has_rims && s.basis.edges.pave && !rows_along_rims && !s.adaptive());
  s.basis.edges.rims = rim_row_loops(c.map, design.elements.rim_rows);
  // The adaptive pattern is grown instead of the lattice (docs/topology.md).
  if (s.adaptive()) {
    AdaptivePattern grown = build_adaptive_pattern(c.map, pavement.cell, design, c.options.stop, s.grade.get());
    pavement.pattern = std::move(grown.pattern);
    pavement.relaxation = grown.relaxation;
  } else {
    pavement.pattern = build_pattern(c.map, pavement.cell, design.placement, design.elements.face.enabled);
  }
  s.edited = add_edited_points(c.map, pavement.pattern, design.edits,
                               design.elements.vertex.scale * design.pattern.spacing, design.elements.gap);
  pavement.points = pavement.pattern.points;
  pavement.retired.assign(pavement.points.size(), 0);
  // Before any element is placed or measured: the caller's bounds (run_pipeline's output size)
  // refuse a design here at the cost of its pattern alone.
  if (c.options.on_pattern) c.options.on_pattern(pavement.pattern, design);
}

void measure_initial(const PaveContext& c, PaveState& s) {
  const PlacedElements initial =
      place_all_elements(c.map, s.pavement.pattern, s.pavement.points, s.design.elements, s.design.pattern.spacing,
                         edge_anchor(s.design.pattern.topology), c.options.postprocess, nullptr, s.grade.get());
  s.pavement.before = measure_pavement(c.map, s.pavement.pattern, s.pavement.points, initial.elements, s.basis, nullptr,
                                       Measure::Counts);
}

// --- the optimizer: the adaptive pattern's on the surface, or the paper's spring system ---

void optimize(const PaveContext& c, PaveState& s) {
  Pavement& pavement = s.pavement;
  s.optimized = true;
  if (s.adaptive()) {
    // The adaptive pattern's own optimizer, on the surface, with contact in it; removal is the
    // last resort for what still collides.
    SurfaceSpringOptions relaxing;
    relaxing.grade = s.grade.get();
    pavement.solve = relax_pattern_on_surface(c.map, pavement.pattern, pavement.points, s.design, relaxing, c.options.stop);
    pavement.solve.backend = "cpu";  // the adaptive pattern's optimizer has no GPU path
    return;
  }
  const Design& design = s.design;
  const SolverSurface& surface = s.surface.emplace(make_solver_surface(c.map));
  SpringSystem& system = s.system.emplace(make_spring_system(pavement.pattern));
  apply_guidance(system, pavement.pattern, design.guidance);
  set_aside_added(system, s.edited);
  s.factory = c.options.solver ? c.options.solver : cpu_solver_factory(c.options.threads);
  const PatternAtSpacing pattern_at = [&](double spacing) {
    PatternDesign coarser = design.pattern;
    coarser.spacing = spacing;
    return build_pattern(c.map, make_design_cell(coarser), design.placement);
  };
  // An atlas's charts lie side by side in one uv frame: a field over it would blend them.
  if (!is_atlas(c.map))
    pavement.coarse_start =
        coarse_start(surface, system, pattern_at, design.solver, design.pattern.spacing, s.factory, c.options.stop);
  const std::unique_ptr<SpringSolverBackend> solver = s.factory(surface, system, design.solver, design.pattern.spacing);
  pavement.solve = solver->solve(c.options.observer, c.options.stop);
  pavement.solve.backend = std::string(solver->backend_name());
  for (int i = 0; i < system.particle_count(); ++i) pavement.points[i] = glm::dvec2(system.position[i]);
}

// The elements on the optimized particles (or, unoptimized, on the lifted pattern as laid, the
// edits as put) and the paper's method's figures.
void measure_paper(const PaveContext& c, PaveState& s) {
  Pavement& pavement = s.pavement;
  if (!s.optimized) {
    for (const EditedParticle& e : s.edited) pavement.points[std::size_t(e.particle)] = e.to;
    pavement.elements = s.place(c, pavement.points, {});
    pavement.paper = pavement.before;
    return;
  }
  pavement.elements = s.place(c, pavement.points, s.system ? s.system->stray_count : std::vector<std::uint32_t>{});
  pavement.paper = measure_pavement(c.map, pavement.pattern, pavement.points, pavement.elements, s.basis,
                                    &pavement.retired, Measure::Counts);
}

ElementPlacer placer(const PaveContext& c, PaveState& s) {
  return [&c, &s](const std::vector<glm::dvec2>& points, const std::vector<std::uint32_t>& stray_count) {
    return s.place(c, points, stray_count);
  };
}

void resolve(const PaveContext& c, PaveState& s) {
  Pavement& pavement = s.pavement;
  if (s.adaptive()) {
    const Removal removal = remove_colliding(pavement.elements, s.design.elements.gap);
    pavement.resolution.pairs_left = removal.pairs;
    pavement.resolution.removed = removal.removed;
    pavement.resolution.removed_places = removal.places;
    return;
  }
  pavement.elements = resolve_collisions(c.map, *s.surface, *s.system, pavement.pattern, s.design.elements,
                                         s.design.solver, s.design.pattern.spacing, pavement.points, placer(c, s),
                                         s.factory, c.options.resolution, pavement.resolution, c.options.stop);
}

// The edits placed with the neighbourhood left where it is: the elements, the stones that still
// collide removed at once (never the designer's pinned ones first).
struct EditsInPlace {
  SpringSystem system;
  std::vector<glm::dvec2> points;
  HeldParticles held;
  Elements elements;
  Removal removal;
  // What this placement set on the pavement (PaveState::place), given back if this way is kept.
  std::vector<std::uint8_t> retired;
  int filled = 0, eliminated = 0;
};

// The stones on the edges of a stone the edits moved (one end moved, the other not), put back
// where they were laid (placed from the moved points, they slide half the drag along their edges),
// matched by their pattern edge.
void keep_edge_stones_of_moved(Elements& elements, const Elements& as_laid, const Pattern& pattern,
                               const std::vector<std::uint8_t>& moved) {
  std::map<std::pair<int, int>, std::size_t> laid;  // (edge, spec) -> index in as_laid
  for (std::size_t i = 0; i < as_laid.size(); ++i)
    if (as_laid.kind[i] == ElementKind::Edge && as_laid.source[i] >= 0) laid.emplace(std::pair{as_laid.source[i], as_laid.spec[i]}, i);
  for (std::size_t i = 0; i < elements.size(); ++i) {
    const int edge = elements.source[i];
    if (elements.kind[i] != ElementKind::Edge || edge < 0) continue;
    if (moved[std::size_t(pattern.edge_a[std::size_t(edge)])] == moved[std::size_t(pattern.edge_b[std::size_t(edge)])]) continue;
    const auto was = laid.find({edge, elements.spec[i]});
    if (was == laid.end()) continue;
    const std::size_t j = was->second;
    elements.uv[i] = as_laid.uv[j], elements.position[i] = as_laid.position[j], elements.normal[i] = as_laid.normal[j];
    elements.diameter[i] = as_laid.diameter[j];
  }
}

EditsInPlace edits_in_place(const PaveContext& c, PaveState& s) {
  EditsInPlace way{*s.system, s.pavement.points, {}, {}, {}, {}, 0, 0};
  // Before the edits' own placement: PaveState::place leaves its figures on the pavement.
  const Elements as_laid = s.place(c, s.pavement.points, s.system->stray_count);
  way.held = place_edits(way.system, s.edited, s.design.pattern.spacing, false);
  std::vector<std::uint8_t> moved(std::size_t(way.system.particle_count()), 0);
  for (const EditedParticle& e : s.edited)
    if (!e.added && std::size_t(e.particle) < s.pavement.points.size() &&
        glm::length(e.to - s.pavement.points[std::size_t(e.particle)]) > 1e-9 * s.design.pattern.spacing)
      moved[std::size_t(e.particle)] = 1;
  for (int i = 0; i < way.system.particle_count(); ++i) way.points[std::size_t(i)] = glm::dvec2(way.system.position[std::size_t(i)]);
  way.elements = s.place(c, way.points, way.system.stray_count);
  way.retired = s.pavement.retired;
  way.filled = s.pavement.filled;
  way.eliminated = s.pavement.eliminated;
  // The moved stone's edge stones either ride along (placed from the moved points: a small drag
  // along an edge pushes one of them out of the way) or stay where they were laid (a larger one
  // lands on them instead of sliding them into the stones beyond): whichever keeps more stones,
  // left in place on a tie.
  Elements stayed = way.elements;
  keep_edge_stones_of_moved(stayed, as_laid, s.pavement.pattern, moved);
  std::vector<std::uint8_t> pinned = pinned_vertex_elements(way.elements, way.system), pinned_stayed = pinned;
  way.removal = remove_colliding(way.elements, s.design.elements.gap, &pinned);
  Removal removal_stayed = remove_colliding(stayed, s.design.elements.gap, &pinned_stayed);
  if (stayed.size() >= way.elements.size()) {
    way.elements = std::move(stayed);
    way.removal = std::move(removal_stayed);
  }
  return way;
}

// The edits start from the design's own pavement and change it only around them, one of two ways,
// whichever keeps more stones (the first when equal): the neighbourhood carried along by the soft
// selection and pushed apart by contact springs, or left in place with what the edit overlaps
// removed. Tight pavé has no room to push into: there the first way pressed a chain of stones up to
// the edge of reach (a 0.25 D drag on the bundled pendant's gems lost 29 of them), the second loses
// only what the dragged stone lands on.
void apply_edits(const PaveContext& c, PaveState& s) {
  Pavement& pavement = s.pavement;
  SpringSystem& system = *s.system;
  // A deleted pattern stone (its id is its point's) sits the edits out: deleted, then a stone added
  // at its place, it was removed as colliding with the added one and its deletion said it found
  // none. It comes back as it was afterwards, so that the refill sees no hole there, and the
  // deletions step takes it as before.
  std::vector<std::uint32_t> own_count;
  std::vector<std::uint8_t> point_deleted(std::size_t(pavement.pattern.point_count()), 0);
  for (const DeletedElement& deleted : s.design.edits.deleted)
    if (deleted.id >= 0 && deleted.id < pavement.pattern.point_count() &&
        system.stray_count[std::size_t(deleted.id)] != kRetired) {
      own_count.push_back(system.stray_count[std::size_t(deleted.id)]);
      system.stray_count[std::size_t(deleted.id)] = kRetired;
      s.deleted_before_edits.push_back(deleted.id);
      point_deleted[std::size_t(deleted.id)] = 1;
    }
  // The deleted stones as they stand, kept aside (erase_flagged drops the others from the copy).
  std::vector<std::uint8_t> not_deleted(pavement.elements.size(), 1);
  for (std::size_t i = 0; i < pavement.elements.size(); ++i)
    if (pavement.elements.kind[i] == ElementKind::Vertex && pavement.elements.source[i] >= 0 &&
        point_deleted[std::size_t(pavement.elements.source[i])])
      not_deleted[i] = 0;
  Elements deleted_stones = pavement.elements;
  deleted_stones.erase_flagged(not_deleted);
  const auto bring_back = [&] {
    for (std::size_t k = 0; k < s.deleted_before_edits.size(); ++k)
      system.stray_count[std::size_t(s.deleted_before_edits[k])] = own_count[k];
    pavement.elements.append(deleted_stones);
  };
  const bool resolve = c.options.resolve_collisions && !s.design.elements.allow_overlap;
  std::optional<EditsInPlace> in_place;
  if (resolve) in_place.emplace(edits_in_place(c, s));
  const HeldParticles beyond = place_edits(system, s.edited, s.design.pattern.spacing);
  for (int i = 0; i < system.particle_count(); ++i) pavement.points[i] = glm::dvec2(system.position[i]);
  if (!resolve) {
    pavement.elements = s.place(c, pavement.points, system.stray_count);
    release_held(system, beyond);
    bring_back();
    return;
  }
  CollisionResolutionReport around;
  // An edit's few collisions are the designer's: pushed apart in every round, never left to the
  // last resort early, whatever the pattern's size.
  CollisionResolutionOptions every_round = c.options.resolution;
  every_round.large_pattern_particles = std::numeric_limits<int>::max();
  pavement.elements = resolve_collisions(c.map, *s.surface, system, pavement.pattern, s.design.elements,
                                         s.design.solver, s.design.pattern.spacing, pavement.points, placer(c, s),
                                         s.factory, every_round, around, c.options.stop);
  pavement.resolution.rounds += around.rounds;
  pavement.resolution.contact_springs += around.contact_springs;
  pavement.resolution.solver_iterations += around.solver_iterations;
  pavement.resolution.retired += around.retired;
  // The final elements are this resolution's.
  pavement.resolution.removed = around.removed;
  pavement.resolution.removed_places = std::move(around.removed_places);
  release_held(system, beyond);
  if (in_place->elements.size() > pavement.elements.size()) {
    system = std::move(in_place->system);
    release_held(system, in_place->held);
    pavement.points = std::move(in_place->points);
    pavement.elements = std::move(in_place->elements);
    pavement.retired = std::move(in_place->retired);
    pavement.filled = in_place->filled;
    pavement.eliminated = in_place->eliminated;
    pavement.resolution.removed = in_place->removal.removed;
    pavement.resolution.removed_places = std::move(in_place->removal.places);
  }
  bring_back();
}

// --- after the solve: rows along the rims, the bare regions refilled, ids, the final figures ---

void lay_rim_rows(const PaveContext& c, PaveState& s) {
  s.pavement.rim_rows = place_rim_rows(c.map, s.pavement.elements, s.design.elements, s.design.pattern.spacing);
}

void refill(const PaveContext& c, PaveState& s) {
  Pavement& pavement = s.pavement;
  // Across a closed surface's seams first, so that the bare regions' refill grows from there too.
  RefillReport seams;
  // The refill adds V-elements: at the V-elements' own density, not all elements' (a honeycomb
  // with edge elements has room in every hexagon at the mixed density).
  const RefillDensity density{
      s.basis.vertex_share > 0 ? s.basis.area_per_element / s.basis.vertex_share : s.basis.area_per_element,
      s.design.solver.c, s.design.solver.m};
  const ElementsDesign& spec = s.design.elements;
  const double spacing = s.design.pattern.spacing;
  refill_seams(c.map, pavement.elements, spec, spacing, density, seams);
  pavement.refill = refill_bare_regions(c.map, pavement.elements, spec, spacing, density, c.options.stop);
  pavement.refill.added += seams.added;
  pavement.refill.on_seams = seams.on_seams;
  pavement.refill.milliseconds += seams.milliseconds;
}

void close_spots(const PaveContext& c, PaveState& s) {
  const ElementsDesign& spec = s.design.elements;
  const double spacing = s.design.pattern.spacing;
  SpotClosing& closed = s.pavement.spots_closed;
  const Elements& elements = s.pavement.elements;
  if (elements.size() > kMostStonesClosed) {
    closed.too_many_stones = true;  // said by run_pipeline's warnings
    return;
  }
  // The designer's moved and added stones hold: the pushing moves the pattern's own around them.
  const int designed = s.pavement.pattern.designed_point_count();
  std::set<int> moved;
  for (const MovedParticle& m : s.design.edits.moved) moved.insert(m.id);
  std::vector<char> held(elements.size(), 0);
  for (std::size_t i = 0; i < elements.size(); ++i)
    held[i] = elements.kind[i] == ElementKind::Vertex && elements.source[i] >= 0 &&
              (elements.source[i] >= designed || moved.count(elements.source[i]) > 0);
  closed = close_bare_spots(c.map, s.pavement.elements, spec, spacing, s.basis.edges.spots, c.options.stop, &held);
  // A design with smaller stones on its edges (pavé with melee between) has those stones to hand:
  // where no V-stone can be pushed in, a spot takes the largest of them that fits, as stocked sizes
  // fill (the pushing moves same-size V-stones only, and left the pierced pendant's 15 spots). The
  // fill orders the sizes and drops those not under the main stone itself.
  ElementsDesign edge_sizes = spec;
  edge_sizes.fill_sizes.clear();
  for (const EdgeElementDesign& e : spec.edge)
    if (e.shape == spec.vertex.shape) edge_sizes.fill_sizes.push_back(e.scale * spacing);
  if (!spec.vertex.enabled || edge_sizes.fill_sizes.empty()) return;
  const SizeFill fill =
      fill_with_smaller_sizes(c.map, s.pavement.elements, edge_sizes, spec.vertex.scale * spacing, c.options.stop);
  closed.added += fill.added();
  closed.of_edge_size = fill.added();
  closed.milliseconds += fill.milliseconds;
}

// The stones the rim rows, the refill and the spots added at the main size take their grade too;
// then the room the grown pattern left between graded stones gets the largest of the ladder's
// sizes that fits, as stocked sizes fill (a narrow band's packing removes a few jammed stones).
// The fill sizes come after, so every V-element under the main size now is a graded one.
void grade(const PaveContext& c, PaveState& s) {
  Elements& elements = s.pavement.elements;
  grade_stones(c.map, *s.grade, elements);
  ElementsDesign ladder = s.design.elements;
  ladder.fill_sizes.assign(s.grade->ladder().begin() + 1, s.grade->ladder().end());
  s.pavement.grade.filled = fill_with_smaller_sizes(c.map, elements, ladder, s.grade->main(), c.options.stop).added();
  s.pavement.grade.graded = 0;
  for (std::size_t i = 0; i < elements.size(); ++i)
    s.pavement.grade.graded += elements.kind[i] == ElementKind::Vertex && elements.diameter[i] < s.grade->main();
}

void fill_sizes(const PaveContext& c, PaveState& s) {
  const ElementsDesign& spec = s.design.elements;
  s.pavement.size_fill =
      fill_with_smaller_sizes(c.map, s.pavement.elements, spec, spec.vertex.scale * s.design.pattern.spacing, c.options.stop);
}

void number(const PaveContext&, PaveState& s) {
  number_elements(s.pavement.elements, s.pavement.pattern, s.design.edits.added);
}

void delete_edited(const PaveContext&, PaveState& s) {
  s.pavement.deletions_missed =
      delete_elements(s.pavement.elements, s.design.edits, first_refill_id(s.pavement.pattern));
}

void measure_final(const PaveContext& c, PaveState& s) {
  Pavement& pavement = s.pavement;
  pavement.after =
      measure_pavement(c.map, pavement.pattern, pavement.points, pavement.elements, s.basis, &pavement.retired);
}

void lay_beads(const PaveContext& c, PaveState& s) {
  // The bead sizes are millimetres (a caster's), the surface's unit may not be.
  ElementsDesign spec = s.design.elements;
  const double per_mm = 1 / millimetres_per_unit(s.design.units);
  spec.beads.min_diameter *= per_mm;
  spec.beads.over *= per_mm;
  s.pavement.beads = place_beads(c.map, s.pavement.elements, spec);
  number_beads(s.pavement.beads, s.pavement.elements);
}

// A step's condition: nullptr when it always runs.
using Applies = bool (*)(const PaveState&, const PavementOptions&);
constexpr Applies kLatticeEdits = [](const PaveState& s, const PavementOptions&) {
  return s.lattice_solved() && !s.edited.empty();
};
constexpr Applies kWithoutOverlap = [](const PaveState& s, const PavementOptions&) {
  return !s.design.elements.allow_overlap;
};

// Spots are closed when the design asks, for pave (report/edge_quality.h), in a pavement the
// optimizer made that holds together: a torn lattice or one with bare patches is the adaptive
// pattern's to mend (pattern.topology auto tries it), not the spots'.
constexpr Applies closes_spots = [](const PaveState& s, const PavementOptions& o) {
  const double ideal = s.basis.ideal_count;
  return s.design.elements.close_spots && s.basis.edges.pave && s.optimized && o.refill && kWithoutOverlap(s, o) &&
         !pattern_is_torn(s.pavement.paper) && !(ideal > 0 && double(s.pavement.elements.size()) < kBareFill * ideal);
};

constexpr PaveStep kSteps[] = {
    {"pattern", nullptr, lay_out_pattern},
    {"measure_initial", nullptr, measure_initial},
    {"optimize",
     [](const PaveState& s, const PavementOptions& o) { return o.optimize && s.pavement.pattern.point_count() > 0; },
     optimize},
    {"measure_paper", nullptr, measure_paper},
    {"resolve_collisions",
     [](const PaveState& s, const PavementOptions& o) {
       return s.optimized && o.resolve_collisions && kWithoutOverlap(s, o);
     },
     resolve},
    {"edits", kLatticeEdits, apply_edits},
    {"rim_rows",
     [](const PaveState& s, const PavementOptions& o) {
       return s.design.elements.rim_rows != RimRows::None && kWithoutOverlap(s, o);
     },
     lay_rim_rows},
    {"refill", [](const PaveState& s, const PavementOptions& o) { return o.refill && kWithoutOverlap(s, o); }, refill},
    {"close_spots", closes_spots, close_spots},
    {"grade", [](const PaveState& s, const PavementOptions&) { return s.grade != nullptr; }, grade},
    {"fill_sizes",
     [](const PaveState& s, const PavementOptions& o) {
       return !s.design.elements.fill_sizes.empty() && s.design.elements.vertex.enabled && kWithoutOverlap(s, o);
     },
     fill_sizes},
    {"ids", nullptr, number},
    {"deletions", [](const PaveState& s, const PavementOptions&) { return !s.design.edits.deleted.empty(); },
     delete_edited},
    {"measure", nullptr, measure_final},
    {"beads", [](const PaveState& s, const PavementOptions&) { return s.design.elements.beads.enabled; }, lay_beads},
};

// Runs the steps from the first until `until` (all when it names none); each timed and named to
// the caller, and none after a stop is asked (the caller ends the run).
void run_steps(const PaveContext& context, PaveState& state, std::string_view until) {
  for (const PaveStep& step : kSteps) {
    if (step.name == until) return;
    if (context.options.stop && context.options.stop->load()) return;
    if (step.applies && !step.applies(state, context.options)) continue;
    if (context.options.on_stage) context.options.on_stage(step.name);
    const Stopwatch watch;
    step.run(context, state);
    state.pavement.timings.emplace_back(step.name, watch.milliseconds());
  }
}

}  // namespace

RowAlignment fold_row_alignment(const SurfaceMap& map, const UnitCell& cell, Placement& placement) {
  const std::optional<RowAlignment> aligned = align_rows(map, cell, placement.align);
  if (!aligned)
    throw DesignError(key_path(Key::align) + ": the " + std::string(enum_name(placement.align)) +
                      " axis is normal to the surface almost everywhere, so rows cannot follow it; use another "
                      "axis or none");
  placement.rotation_deg += aligned->rotation_deg;
  placement.align = AlignAxis::None;
  return *aligned;
}

std::span<const PaveStep> pave_steps() { return kSteps; }

PaveState pave_until(const SurfaceMap& map, Design design, const PavementOptions& options, std::string_view until) {
  PaveState state;
  state.design = std::move(design);
  run_steps(PaveContext{map, options}, state, until);
  return state;
}

void pave_step(std::string_view name, const SurfaceMap& map, const PavementOptions& options, PaveState& state) {
  for (const PaveStep& step : kSteps)
    if (step.name == name) return step.run(PaveContext{map, options}, state);
  throw std::invalid_argument("pave_step: no step named " + std::string(name));
}

Pavement pave_once(const SurfaceMap& map, Design design, const PavementOptions& options) {
  PaveState state = pave_until(map, std::move(design), options, "");
  state.pavement.design = std::move(state.design);
  return std::move(state.pavement);
}

}  // namespace paver
