#include "pipeline/offset_fit.h"

#include "core/input_error.h"
#include "pattern/pattern.h"
#include "elements/boundary_postprocess.h"

#include <tbb/parallel_for.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace paver {

OffsetFit fit_offset(const SurfaceMap& map, const UnitCell& cell, const ElementsDesign& elements,
                     const Placement& placement, const std::atomic<bool>* stop) {
  const double points = std::max(1.0, estimate_point_count(map, cell, placement));
  const int k = std::clamp(static_cast<int>(std::sqrt(kOffsetFitPointBudget / points)), 2, 8);
  const int tries = k * k;
  std::vector<OffsetCandidate> candidate(static_cast<std::size_t>(tries));
  // The tries are independent: side by side, but one at a time for a large pattern, whose every
  // try holds a pattern and its elements (about 200 bytes a point) besides the run's own.
  const auto stopped = [&] { return stop && stop->load(); };
  for (int t = 0; t < tries; ++t) {
    OffsetCandidate& c = candidate[t];
    c.shift_in_cells = glm::dvec2(double(t / k) / k, double(t % k) / k);
    c.offset = placement.offset + c.shift_in_cells.x * cell.a1 + c.shift_in_cells.y * cell.a2;
  }
  const auto lay_out = [&](int t) {
    if (stopped()) return;
    OffsetCandidate& c = candidate[t];
    Placement shifted = placement;
    shifted.offset = c.offset;
    c.laid_out = laid_out_count(map, cell, elements, shifted);
  };
  if (points <= kOffsetFitParallelPoints)
    tbb::parallel_for(0, tries, lay_out);
  else
    for (int t = 0; t < tries; ++t) lay_out(t);
  // A shift by a whole cell repeats the lattice, so the neighbours wrap around.
  const auto at = [&](int i, int j) { return candidate[((i + k) % k) * k + (j + k) % k].laid_out; };
  std::vector<std::size_t> around(candidate.size());
  std::vector<int> steps(candidate.size());  // from no shift, around the cell
  for (int t = 0; t < tries; ++t) {
    const int i = t / k, j = t % k;
    for (int di = -1; di <= 1; ++di)
      for (int dj = -1; dj <= 1; ++dj) around[t] += at(i + di, j + dj);
    steps[t] = std::min(i, k - i) + std::min(j, k - j);
  }
  std::vector<int> ranked(candidate.size());
  for (int t = 0; t < tries; ++t) ranked[t] = t;
  std::stable_sort(ranked.begin(), ranked.end(), [&](int a, int b) {
    if (candidate[a].laid_out != candidate[b].laid_out) return candidate[a].laid_out > candidate[b].laid_out;
    if (around[a] != around[b]) return around[a] > around[b];
    return steps[a] < steps[b];
  });
  OffsetFit fit;
  fit.tries = tries;
  fit.at_design = candidate[0];
  if (stopped()) {  // the counts are partial: no shift; the caller ends the run
    fit.chosen = candidate[0];
    return fit;
  }
  fit.chosen = candidate[ranked[0]];
  if (points <= kOffsetFitPavedPoints) {
    for (int r = 0; r < std::min(kOffsetFitFinalists, tries); ++r) fit.finalists.push_back(candidate[ranked[r]]);
    if (std::find(ranked.begin(), ranked.begin() + fit.finalists.size(), 0) == ranked.begin() + fit.finalists.size())
      fit.finalists.push_back(candidate[0]);
  }
  return fit;
}

// Rows that run along a band's rims are kept or lost whole at each rim, so where the lattice sits
// across the band decides how many fit: of shifts across (a sixteenth of a row apart, on top of
// the design's offset), those whose laid-out elements keep the most after the boundary
// post-processing. Shifts that keep the same rows form a run; its middle leaves the rows as far
// from one rim as from the other (the first of them put a ring's rows 0.03 mm from one rim and
// 0.49 mm from the other).
glm::dvec2 best_offset_across(const SurfaceMap& map, const UnitCell& cell, const ElementsDesign& elements,
                              const Placement& placement, glm::ivec2 step) {
  constexpr int kTries = 16;
  const double angle = placement.rotation_deg * std::numbers::pi / 180.0;
  const glm::dvec2 across(-std::sin(angle), std::cos(angle));  // the band's v in the pattern plane
  // Rows along the repeating step lie this far apart: a shift by it lays the rows where rows were
  // (the stones along them may move), so the tries span it.
  const double band_step =
      std::abs(cell.cell_area()) / glm::length(double(step.x) * cell.a1 + double(step.y) * cell.a2);
  // The tries start where the design's offset has no part across the band: the design.json a run
  // writes holds the offset found, and run again it must find the same one (from its own offset
  // the tries moved the rows half a row further on every run where all shifts keep as many). The
  // search replaces the design's offset across the band; along it, the offset is the design's.
  const glm::dvec2 base = placement.offset - glm::dot(placement.offset, across) * across;
  // The tries are independent: side by side (a large band's layout is mostly serial).
  std::array<std::size_t, kTries> count{};
  tbb::parallel_for(0, kTries, [&](int k) {
    Placement shifted = placement;
    shifted.offset = base + (band_step * k / kTries) * across;
    count[k] = laid_out_count(map, cell, elements, shifted);
  });
  const std::size_t most = *std::max_element(count.begin(), count.end());
  // The longest run of shifts that keep the most, around the circle (a shift by a whole row
  // repeats the lattice); its middle, half-way between two shifts when its length is even.
  int best_start = 0, best_length = 0;
  for (int start = 0; start < kTries; ++start) {
    if (count[start] != most || count[(start + kTries - 1) % kTries] == most) continue;  // not a run's start
    int length = 0;
    while (length < kTries && count[(start + length) % kTries] == most) ++length;
    if (length > best_length) best_start = start, best_length = length;
  }
  if (best_length == 0) best_length = kTries;  // every shift keeps as many: any will do
  const double middle = best_start + 0.5 * (best_length - 1);
  return base + (band_step * middle / kTries) * across;
}

std::size_t laid_out_count(const SurfaceMap& map, const UnitCell& cell, const ElementsDesign& elements,
                           const Placement& placement) {
  try {
    const Pattern pattern = build_pattern(map, cell, placement, elements.face.enabled);
    return place_all_elements(map, pattern, pattern.points, elements, cell.spacing, EdgeAnchor::MapLine, true)
        .elements.size();
  } catch (const InputError&) {
    // No point of this shift lands on the map (a narrow ring at a large D): it lays out nothing,
    // and another shift may do better. A fault of every shift is said by the pattern built after.
    return 0;
  }
}

}  // namespace paver
