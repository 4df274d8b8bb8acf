#include "pattern/band_closure.h"
#include "core/number_text.h"

#include "core/input_error.h"
#include "pattern/design_cell.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

namespace paver {
namespace {

// The lattice vector that repeats around the band: along the rows, the shortest one; across
// them, the one most nearly square to it (the shortest of those).
glm::ivec2 repeating_step(const UnitCell& cell, bool across) {
  const auto vector_of = [&](glm::ivec2 m) { return double(m.x) * cell.a1 + double(m.y) * cell.a2; };
  constexpr int kReach = 3;
  glm::ivec2 along(1, 0);
  for (int i = -kReach; i <= kReach; ++i)
    for (int j = 0; j <= kReach; ++j) {
      const glm::ivec2 m(i, j);
      if ((j == 0 && i <= 0) || glm::length(vector_of(m)) >= glm::length(vector_of(along)) * (1 - 1e-9)) continue;
      along = m;
    }
  if (!across) return along;
  const glm::dvec2 row = glm::normalize(vector_of(along));
  glm::ivec2 best(0, 0);
  double best_cos = 2, best_length = 0;
  for (int i = -kReach; i <= kReach; ++i)
    for (int j = 0; j <= kReach; ++j) {
      const glm::ivec2 m(i, j);
      if (j == 0 && i <= 0) continue;
      const double length = glm::length(vector_of(m));
      const double c = std::abs(glm::dot(vector_of(m), row)) / length;
      if (c < best_cos - 1e-9 || (c < best_cos + 1e-9 && length < best_length))
        best = m, best_cos = c, best_length = length;
    }
  return best;
}

}  // namespace

BandClosure close_band(const SurfaceMap& map, const UnitCell& cell, const Placement& placement, bool never_closer) {
  BandClosure closure;
  closure.rows_across = placement.band_rows == BandRows::Across;
  closure.spacing_before = cell.spacing;
  closure.step = repeating_step(cell, closure.rows_across);
  const glm::dvec2 v = double(closure.step.x) * cell.a1 + double(closure.step.y) * cell.a2;
  closure.rotation_deg = std::atan2(v.y, v.x) * 180.0 / std::numbers::pi;
  const double around_length = map.period * placement.scale;  // T in the pattern plane
  const double raw_steps = around_length / glm::length(v);
  // A D that already closes the band (a saved design re-run) gives a whole number of steps but
  // for rounding, 42.9999999 or 43.0000001: it must close it again at the same D, not one fewer.
  const double whole = std::round(raw_steps);
  const double steps = std::abs(raw_steps - whole) < 1e-9 * raw_steps ? whole : raw_steps;
  // At least three steps around: fewer would join a point to itself or twice to another. Elements
  // that may not come closer (stones, or a gap at its limit) then need room for three.
  if (never_closer && steps < 3) {
    throw InputError(std::string("rows ") + (closure.rows_across ? "across" : "along") +
                     " the band need 3 lattice steps around it, and " + significant_text(steps) +
                     " fit at this D: the elements cannot come closer to close it (that way D is at most " +
                     significant_text(cell.spacing * steps / 3, 4) + ")");
  }
  closure.around = std::max(3, int(never_closer ? std::floor(steps) : std::round(steps)));
  // Closed already: D stays as it is to the last bit, so a saved design paves as it did.
  closure.spacing = double(closure.around) == steps
                        ? cell.spacing
                        : cell.spacing * around_length / (closure.around * glm::length(v));
  return closure;
}

namespace {

// "0.1 -> 0.128 (+1.3% of D)": the lattice's gap once the band is closed.
std::string gap_change(const BandClosure& c) {
  return significant_text(c.gap_asked, 4) + " -> " + significant_text(c.lattice_gap(), 4) + " (+" +
         rounded_figure_text(100 * (c.spacing - c.spacing_before) / c.spacing_before) + "% of D)";
}

}  // namespace

std::string describe_band_closure(const BandClosure& closure) {
  return "D " + significant_text(closure.spacing_before, 4) + " -> " + significant_text(closure.spacing, 4) + ": " + std::to_string(closure.around) +
         " lattice steps close the band (rows " + (closure.rows_across ? "across" : "along") + " it)" +
         (closure.stones_kept ? "; the stones keep their size, the gap takes the change: " + gap_change(closure) : "") +
         band_rows_choice(closure);
}

std::string band_rows_choice(const BandClosure& c) {
  if (c.laid_out_across + c.laid_out_along == 0) return "";
  const bool paved = c.kept_across + c.kept_along > 0;
  const std::string across = std::to_string(paved ? c.kept_across : c.laid_out_across);
  const std::string along = std::to_string(paved ? c.kept_along : c.laid_out_along);
  const std::string verb = paved ? " kept " : " laid out ";
  return "; rows auto: " + (c.rows_across ? "across" + verb + across + " elements, along " + along
                                          : "along" + verb + along + " elements, across " + across);
}

ClosedBand close_band_design(const SurfaceMap& map, Design design, BandRows rows) {
  design.placement.band_rows = rows;
  // Stones (gem elements) come in catalogue sizes: they keep their diameter, the gap takes the
  // change, and so D may only grow. Other elements are sized with D, as everywhere.
  const bool stones = keeps_stone_sizes(design.elements);
  const UnitCell cell = make_design_cell(design.pattern);
  BandClosure closure = close_band(map, cell, design.placement, stones);
  if (stones) {
    keep_stone_sizes(design.elements, closure.spacing_before, closure.spacing);
    closure.stones_kept = true;
    closure.gap_asked = design.elements.gap;
  } else if (closure.spacing < design.pattern.spacing) {
    // Closer elements may break the design's gap, which is in surface units: then one step fewer.
    Design closer = design;
    closer.pattern.spacing = closure.spacing;
    try {
      check_design_cell(closer);
    } catch (const InputError&) {
      closure = close_band(map, cell, design.placement, true);
    }
  }
  design.pattern.spacing = closure.spacing;
  design.placement.rotation_deg = closure.rotation_deg;
  return {std::move(design), closure};
}

}  // namespace paver
