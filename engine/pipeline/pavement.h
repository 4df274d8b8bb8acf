#pragma once
// From a surface map and a design to elements (sections 4.1, 4.2, 5): the unit cell with the
// design's operators, the trimmed pattern, the optimized particles, the elements lifted to the
// surface, post-processing, collision resolution and the quality figures. run_pipeline calls it
// after mapping; the studio re-runs it (through run_pipeline, on its map) on every design change.
// The pass itself is pipeline/pave_once.h; the choices above it pipeline/choices.h.
#include "pattern/particle_relaxation.h"
#include "solver/coarse_start.h"
#include "solver/collision_resolution.h"
#include "elements/bare_spots.h"
#include "elements/boundary_postprocess.h"
#include "elements/refill.h"
#include "elements/stone_grade.h"
#include "elements/stone_sizes.h"
#include "elements/rim_rows.h"
#include "design/design.h"
#include "elements/elements.h"
#include "map/surface_map.h"
#include "pattern/band_closure.h"
#include "pattern/design_cell.h"
#include "pattern/pattern.h"
#include "pattern/row_alignment.h"
#include "pattern/unit_cell.h"
#include "pipeline/offset_fit.h"
#include "report/pavement_quality.h"
#include "solver/spring_solver.h"

#include <functional>
#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace paver {

// Wall-clock milliseconds per named stage, in pipeline order.
using StageTimings = std::vector<std::pair<std::string, double>>;

struct PavementOptions {
  bool optimize = true;              // run the section 5 solver
  bool postprocess = true;           // section 5.4: fill boundary edges, eliminate crossing elements
  bool resolve_collisions = true;    // beyond the paper: contact springs until no pair collides
  bool refill = true;                // beyond the paper: elements into bare regions (elements/refill.h)
  CollisionResolutionOptions resolution;
  int threads = 0;                   // CPU solver threads, 0 = all cores
  SolverFactory solver;              // the backend; empty = the CPU reference with `threads`
  SolverObserver observer;           // called after every solver iteration of the main solve
  const std::atomic<bool>* stop = nullptr;  // when it becomes true, every solve of the run ends
  // Called once the trimmed pattern is built, before any element is placed and before the solver
  // moves it (the studio's live view starts from it), with the design as used (spacing resolved).
  std::function<void(const Pattern&, const Design&)> on_pattern;
  // Called as each stage starts, with its name in `timings` ("pattern", "optimize", "refill", ...).
  std::function<void(const std::string&)> on_stage;
};

struct Pavement {
  Design design;                     // as used: spacing resolved
  UnitCell cell;                     // after operators and bracing
  Pattern pattern;                   // trimmed pattern S^
  std::vector<glm::dvec2> points;    // particle positions: optimised (or the pattern's)
  std::vector<std::uint8_t> retired; // #P 1 for particles the optimizer retired (pushed out for good)
  Elements elements;                 // final elements
  Elements beads;                    // shared prongs between stones, when the design asks (elements/beads.h)
  int filled = 0;                    // E-elements added by boundary filling
  int eliminated = 0;                // elements removed for crossing the boundary
  SolveReport solve;                 // iterations, stop reason, time
  CoarseStartReport coarse_start;    // the lattice's multilevel start (solver/coarse_start.h)
  CollisionResolutionReport resolution;
  RefillReport refill;
  SpotClosing spots_closed;          // stones put into bare spots (elements/bare_spots.h)
  SizeFill size_fill;                // smaller stocked sizes filled in (elements/stone_sizes.h)
  GradeReport grade;                 // graded stones (elements/stone_grade.h)
  RimRowReport rim_rows;
  RelaxationReport relaxation;       // the adaptive pattern's particle relaxation
  // For pattern.topology "auto": which topology was kept and why (design.pattern.topology says
  // which); empty otherwise.
  std::string topology_choice;
  int deletions_missed = 0;          // design.edits.deleted entries that found no element
  // A band's lattice is paved on its seamless map (SurfaceMap::seamless): then `points` are in
  // that map's frame, and `band_closure` says how the lattice was closed around it.
  bool seamless = false;
  // Rows along a world axis (placement.align): the rotation added to rotation_deg; the design
  // above then holds the sum, with align none, so that its design.json repeats the same lattice.
  std::optional<RowAlignment> row_alignment;
  // placement.fit_offset: the offset found; the design above holds it, with fit_offset false.
  std::optional<OffsetFit> offset_fit;
  std::optional<BandClosure> band_closure;
  PavementQuality before;            // the initial pavement, post-processed the same way
  PavementQuality paper;             // after the paper's optimizer and post-processing alone
  PavementQuality after;             // the final pavement
  StageTimings timings;
};

// What the exports and the views show: the stones, then the beads (stone i keeps index i). The
// pavement's own elements when it has no beads; otherwise a copy made in `storage`. `colours`
// (one per stone, if given) gets the beads' metal colour appended.
const Elements& stones_and_beads(const Pavement& pavement, Elements& storage,
                                 std::vector<std::array<std::uint8_t, 3>>* colours = nullptr);

// The map a pattern of this topology is laid on: a band's seamless map for the lattice (the first
// pass of "auto" too), else `map`.
const SurfaceMap& map_for_topology(const SurfaceMap& map, Topology topology);

// Why a band was paved as an annulus, not seamlessly ("" when it was seamless or is no band):
// for the summary and report.json.
std::string band_annulus_reason(const SurfaceMap& map, const Pavement& pavement);

// The map `pavement.points` are on: the surface's seamless map for a seamless pavement, else `map`.
const SurfaceMap& pavement_map(const SurfaceMap& map, const Pavement& pavement);

// The pavement of `design` on `map` (the surface's own map; a band's seamless one is its
// `seamless`): the design's checks first (pattern/design_cell.h), spacing 0 resolved to the
// surface's default, then every automatic choice made by the chooser (pipeline/choices.h) and the
// pass run on the design each choice leaves (pipeline/pave_once.h):
// - pattern.topology auto: the lattice, and where it tears or leaves bare patches (the verdict's
//   bounds) a band's lattice on its annulus map too, and on a design it can take the adaptive
//   pattern; the kept pavement's design says which, its topology_choice why;
// - placement.band_rows auto on a band: both ways, paved when small (else the way that lays out
//   more), Pavement::band_closure says what each kept;
// - placement.fit_offset: shifts laid out, the best few paved (Pavement::offset_fit).
// The candidates dropped are timed as "<name>_tried" (or the choice's own stage).
Pavement make_pavement(const SurfaceMap& map, Design design, const PavementOptions& options = {});

}  // namespace paver
