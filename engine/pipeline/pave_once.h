#pragma once
// One pass from a surface map and a concrete design to a pavement (sections 4.1, 4.2, 5): a table
// of steps (lay out the pattern, measure the initial pavement, optimize, place and measure,
// resolve collisions, the designer's edits, rim rows, refill, ids, deletions, the final measure,
// beads), each with the condition it applies under, run in order in one loop that times each,
// names it to the caller (PavementOptions::on_stage) and ends the pass when a stop is asked.
// A new feature is one step row (and a report field). No choice is made here: the design's auto
// keys are resolved above the pass, by the chooser (pipeline/choices.h).
#include "pattern/pattern_edits.h"
#include "pipeline/pavement.h"
#include "report/pavement_quality.h"
#include "solver/solver_surface.h"
#include "solver/spring_system.h"

#include <memory>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace paver {

// What every step reads: the map the pattern is laid on (a band's seamless map for its lattice)
// and the caller's options.
struct PaveContext {
  const SurfaceMap& map;
  const PavementOptions& options;
};

// What the steps hand on to each other.
struct PaveState {
  Design design;                       // concrete: after the pattern step, its spacing and rows resolved
  Pavement pavement;                   // being built; pavement.design is set when the pass ends
  QualityBasis basis;                  // what fill and the violations are measured against
  std::vector<EditedParticle> edited;  // the designer's moved and added particles
  // Deleted pattern stones that sat the edits' resolution out (apply_edits in pave_once.cpp).
  std::vector<int> deleted_before_edits;
  // The lattice's solve, kept for the resolution and the edits that re-solve it.
  std::optional<SolverSurface> surface;
  std::optional<SpringSystem> system;
  SolverFactory factory;
  bool optimized = false;  // the optimizer ran (else the lifted pattern stays as laid)
  // Graded stones: the field every placement grades by (null when the design has no grade).
  std::shared_ptr<const GradeField> grade;

  bool adaptive() const { return design.pattern.topology == Topology::Adaptive; }
  bool lattice_solved() const { return optimized && !adaptive(); }
  // The elements on `points`, post-processed, skipping the particles `stray_count` retired
  // (pavement.retired follows it); pavement.filled and .eliminated are this placement's.
  Elements place(const PaveContext& context, const std::vector<glm::dvec2>& points,
                 const std::vector<std::uint32_t>& stray_count);
};

struct PaveStep {
  const char* name;  // its timing's and progress's name
  bool (*applies)(const PaveState& state, const PavementOptions& options);  // nullptr: always
  void (*run)(const PaveContext& context, PaveState& state);
};

// Rows along a world axis (placement.align; the pattern step does it, but not on a seamless band):
// the turn that lays the cell's first direction along the axis, folded into rotation_deg with align
// set to none, so that the design as used repeats the same lattice. DesignError for an axis normal
// to the surface almost everywhere.
RowAlignment fold_row_alignment(const SurfaceMap& map, const UnitCell& cell, Placement& placement);

// The pass's steps, in order.
std::span<const PaveStep> pave_steps();

// Inputs: the map the pattern is laid on (map_for_topology), a design whose topology is lattice
// or adaptive, whose fit_offset is resolved (or not to be used) and, on a seamless band, whose
// rows are along or across (auto counts as across, as under element edits); a spacing of 0 is the
// surface's default. Output: the pavement, each step timed in pavement.timings.
Pavement pave_once(const SurfaceMap& map, Design design, const PavementOptions& options = {});

// The state after the steps up to (not including) the one named `until`, and the one step named
// `name` run on a state (whether it applies or not): for tests of one step on a fixture state.
PaveState pave_until(const SurfaceMap& map, Design design, const PavementOptions& options, std::string_view until);
void pave_step(std::string_view name, const SurfaceMap& map, const PavementOptions& options, PaveState& state);

}  // namespace paver
