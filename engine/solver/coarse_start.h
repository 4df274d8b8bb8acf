#pragma once
// A multilevel start for the section 5 solver. Springs pass an imbalance on one row per
// iteration, so a lattice k rows across needs on the order of k^2 iterations to move its density
// to where the map wants it: 200 iterations do that for about 1k points, not for 100k (on the
// lily the lattice tears from 10k points up, docs/solver.md). The same design at twice the
// spacing has a quarter of the points; relaxed (itself from a coarser start), it gives the field
// that moves the regular lattice to its relaxed shape, smooth at that spacing's scale. The
// pattern starts from its own lattice moved by that field, so that its iterations only have to
// settle what the coarse spacing could not see.
#include "design/design.h"
#include "pattern/pattern.h"
#include "solver/solver_backend.h"
#include "solver/solver_surface.h"
#include "solver/spring_system.h"

#include <atomic>
#include <functional>
#include <vector>

namespace paver {

// A coarse level is worth relaxing while it has at least this many points: below, the lattice
// relaxes within the iteration limit on its own.
inline constexpr int kCoarseStartMinPoints = 1000;

struct CoarseStartReport {
  std::vector<int> level_points;  // points of each coarse level relaxed, finest first
  std::vector<int> level_iterations;
  int retired = 0;                // particles the field moved off the map: retired before the solve
  double milliseconds = 0;
};

// The design's pattern (the same cell, placement and trimming) at another spacing.
using PatternAtSpacing = std::function<Pattern(double spacing)>;

// Moves `system`'s particles (the pattern's points at `spacing`) by the displacement field of
// the design relaxed at 2x, 4x, ... the spacing, up to params.coarse_levels levels and while a
// level has kCoarseStartMinPoints points. A particle that the field moves off the map is retired
// (as the solver retires one pushed out persistently). Does nothing on a map that wraps (a
// coarser lattice would not close around the band), when coarse_levels is 0, or when `stop` is
// set while it runs (the particles stay where they were).
CoarseStartReport coarse_start(const SolverSurface& surface, SpringSystem& system, const PatternAtSpacing& pattern_at,
                               const SolverParams& params, double spacing, const SolverFactory& factory,
                               const std::atomic<bool>* stop = nullptr);

}  // namespace paver
