#include "report/verdict.h"

#include "core/number_text.h"

#include <nlohmann/json.hpp>

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
  v.ok = v.problems.empty();
  return v;
}

nlohmann::json to_json(const Verdict& verdict) {
  return nlohmann::json{{"ok", verdict.ok}, {"problems", verdict.problems}};
}

bool paves_better(const PavementQuality& candidate, const PavementQuality& incumbent) {
  const std::size_t mine = judge_pavement(candidate).problems.size(), theirs = judge_pavement(incumbent).problems.size();
  return mine < theirs || (mine == theirs && candidate.fill > incumbent.fill);
}

}  // namespace paver
