#pragma once
// Where the lattice sits over the map (placement.offset) decides how many elements fit: on a
// facade with windows, rows laid along x lost a tenth of their discs at one offset and none at
// another, a quarter of a cell away. These searches shift the lattice by fractions of a cell and
// keep the shift whose laid-out elements keep the most after the boundary post-processing, before
// any optimization (the count before optimizing follows the final count: docs/design_file.md).
#include "design/design.h"
#include "map/surface_map.h"
#include "pattern/unit_cell.h"

#include <glm/vec2.hpp>

#include <atomic>
#include <cstddef>
#include <vector>

namespace paver {

// One shift of the lattice: where it puts the lattice and how many elements it keeps.
struct OffsetCandidate {
  glm::dvec2 offset{0, 0};          // the design's offset plus the shift
  glm::dvec2 shift_in_cells{0, 0};  // the shift, in fractions of a1 and a2
  std::size_t laid_out = 0;         // elements kept after the boundary post-processing, before optimizing
  long kept = -1;                   // elements of the whole pavement; -1 when it was not paved
};

// placement.fit_offset: K x K shifts over one lattice cell (i/K a1 + j/K a2, on top of the
// design's offset) are laid out and counted; for a pattern of up to kOffsetFitPavedPoints points
// the best few and the design's own offset are then paved in full (the optimizer moves elements
// and resolution removes some, so the laid-out count only forecasts the kept one) and the better
// pavement (paves_better, pipeline/choices.h) is laid.
struct OffsetFit {
  OffsetCandidate chosen;
  OffsetCandidate at_design;               // no shift
  int tries = 0;                           // K x K; K is 8, fewer for a large pattern (kOffsetFitPointBudget)
  std::vector<OffsetCandidate> finalists;  // ranked by laid-out count, the design's offset among them; empty
                                           // when the pattern is too large to pave them all
};

// The tries lay out about this many lattice points in all: K = sqrt(budget / points), from 2 to 8
// (a 43,000-point facade took 15 s on 2 cores with 64 tries; 16 take about 4).
inline constexpr double kOffsetFitPointBudget = 1e6;
// Larger patterns are laid out one shift at a time: each try side by side holds a pattern and its
// elements (about 200 bytes a point), and a machine may run dozens of them.
inline constexpr double kOffsetFitParallelPoints = 50000;
// Finalists are paved only for patterns up to this many points: each costs a whole pavement.
inline constexpr double kOffsetFitPavedPoints = 20000;
// The best shifts paved in full, besides the design's own offset.
inline constexpr int kOffsetFitFinalists = 3;

// Lays out the shifts and ranks them: the most laid-out elements first; among equals, the shift
// whose neighbouring shifts keep the most too (the middle of a plateau, not its edge), then the one
// nearest the design's own offset. `chosen` is the first; `finalists` are the best few and the
// design's offset, for the caller to pave (pipeline/choices.cpp), when the pattern is small enough.
// When `stop` becomes true the remaining shifts are skipped and the design's offset is chosen.
// Inputs: the map, the design's cell at its spacing D (cell.spacing), its elements and placement
// (whose offset the shifts start from).
OffsetFit fit_offset(const SurfaceMap& map, const UnitCell& cell, const ElementsDesign& elements,
                     const Placement& placement, const std::atomic<bool>* stop = nullptr);

// The elements that `design` lays out under `placement` before any optimization: the lattice
// placed and post-processed at the boundary (a forecast of the elements kept); 0 where the
// pattern cannot be laid there (InputError: no point lands).
std::size_t laid_out_count(const SurfaceMap& map, const UnitCell& cell, const ElementsDesign& elements,
                           const Placement& placement);

// A band paved seamlessly: its rows run along the rims and are kept or lost whole at each, so only
// the shift across the band matters; `step` is the lattice step that closes around it.
glm::dvec2 best_offset_across(const SurfaceMap& map, const UnitCell& cell, const ElementsDesign& elements,
                              const Placement& placement, glm::ivec2 step);

}  // namespace paver
