#include "report/verdict.h"

#include "core/number_text.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>

namespace paver {
namespace {

std::string format(const char* pattern, double a, double b = 0) {
  char text[200];
  std::snprintf(text, sizeof text, pattern, a, b);
  return text;
}

}  // namespace

Verdict judge_pavement(const PavementQuality& q) {
  Verdict v;
  if (q.elements == 0) v.problems.push_back("no elements were placed");
  if (q.contact_violations > 0)
    v.problems.push_back(count_text(q.contact_violations, "pair is", "pairs are") +
                         format(" closer than their radii plus the gap (smallest clearance %.4g)", q.min_clearance));
  if (q.boundary_crossings > 0)
    v.problems.push_back(count_text(q.boundary_crossings, "element crosses", "elements cross") +
                         (q.margin > 0 ? format(" the surface boundary or its margin of %.4g", q.margin)
                                       : std::string(" the surface boundary")));
  if (pattern_is_torn(q))
    v.problems.push_back(format("the pattern is torn: 5%% of its springs are more than %.0f%% off their "
                                "target (p95 deviation %.3g)",
                                100 * kTornSpringDeviation, q.spring_deviation_p95));
  if (has_bare_patches(q) && !(q.fill > 0))
    v.problems.push_back("the fill could not be measured: a strip half an element wide along the rim covers the "
                         "surface's whole area (a rim that long is spiky or torn), so nothing shows the pavement "
                         "covers it; look at the preview, and smooth the rim or use smaller elements");
  else if (has_bare_patches(q))
    v.problems.push_back(format("bare patches: %.0f%% of the elements that the pattern's density puts on this "
                                "surface (below %.0f%%)",
                                100 * q.fill, 100 * kBareFill));
  if (has_bare_spots(q)) {
    const EdgeQuality& e = q.edges;
    const glm::dvec3 at = e.spots.empty() ? glm::dvec3(0) : e.spots.front().position;
    v.problems.push_back(count_text(e.bare_spots, "bare spot", "bare spots") +
                         format(" where a stone of %.3g still fits (the widest fits %.3g", e.spot_stone, e.largest_fit) +
                         format(", at %.4g, %.4g", at.x, at.y) + format(", %.4g; report.json edges.spots lists them)", at.z));
  }
  if (has_uneven_rim(q))
    v.problems.push_back(format("an uneven rim: the metal between the rim less its margin and the nearest girdle is "
                                "%.2f d at p95 (max %.2f d; above 0.3 d: teeth along it)",
                                q.edges.rim_metal_p95, q.edges.rim_metal_max));
  v.ok = v.problems.empty();
  return v;
}

nlohmann::json to_json(const Verdict& verdict) {
  return nlohmann::json{{"ok", verdict.ok}, {"problems", verdict.problems}};
}

bool paves_better(const PavementQuality& candidate, const PavementQuality& incumbent) {
  // The pavement's soundness first (contact, crossings, a torn or bare pattern), then its edges: a
  // torn lattice with its spots closed lost the vase band to nothing better than it (issue 40).
  const auto sound_problems = [](const PavementQuality& q) {
    return judge_pavement(q).problems.size() - std::size_t(has_bare_spots(q)) - std::size_t(has_uneven_rim(q));
  };
  const std::size_t mine = sound_problems(candidate), theirs = sound_problems(incumbent);
  if (mine != theirs) return mine < theirs;
  if (has_uneven_rim(candidate) != has_uneven_rim(incumbent)) return !has_uneven_rim(candidate);
  const auto spots = [](const PavementQuality& q) { return q.edges.measured && q.edges.pave ? q.edges.bare_spots : 0; };
  if (spots(candidate) != spots(incumbent)) return spots(candidate) < spots(incumbent);
  const bool both_pave = candidate.edges.pave && incumbent.edges.pave;
  if (both_pave && gap_as_asked(candidate) != gap_as_asked(incumbent)) return gap_as_asked(candidate);
  if (both_pave && candidate.edges.rim_samples > 0 && incumbent.edges.rim_samples > 0 &&
      std::abs(candidate.edges.rim_metal_p95 - incumbent.edges.rim_metal_p95) > kRimEvenTie)
    return candidate.edges.rim_metal_p95 < incumbent.edges.rim_metal_p95;
  return candidate.fill > incumbent.fill;
}

}  // namespace paver
