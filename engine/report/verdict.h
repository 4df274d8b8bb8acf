#pragma once
// Whether a pavement is fit to use, in one word and a list of reasons: what the summary prints
// first and report.json carries as `verdict`. A pavement is ok when no pair violates the contact
// rule, no element crosses the boundary, the pattern is not torn and it is not mostly bare.
#include "report/pavement_quality.h"

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace paver {

// A pattern is torn when the 95th percentile of |3D spring length / target - 1| exceeds this:
// springs half their target too long or too short are rips and piles, not the stretch a
// triangle lattice takes on a saddle (0.26 on the bundled saddle, with touching elements).
inline constexpr double kTornSpringDeviation = 0.5;
// Fewer elements than this share of the ideal count (quality `fill`) leaves bare patches.
inline constexpr double kBareFill = 0.85;

// The two problems a map that distorts the lattice causes; judge_pavement names them, and
// topology auto (pipeline/pavement.h) and the CLI's hint act on them.
inline bool pattern_is_torn(const PavementQuality& q) { return q.spring_deviation_p95 > kTornSpringDeviation; }
// A fill that could not be measured (0) is not a pass: the verdict can never say ok under kBareFill.
inline bool has_bare_patches(const PavementQuality& q) { return q.elements > 0 && !(q.fill >= kBareFill); }

struct Verdict {
  bool ok = true;
  std::vector<std::string> problems;  // each a sentence with its figures; empty when ok
};

Verdict judge_pavement(const PavementQuality& final_quality);

// Of two pavements of one surface tried for one design (topology auto, a band's annulus, its rows
// both ways): whether `candidate` is better than `incumbent`: fewer verdict problems, then a
// higher fill (elements over the ideal count at each one's own D). Equal: not better.
bool paves_better(const PavementQuality& candidate, const PavementQuality& incumbent);

nlohmann::json to_json(const Verdict& verdict);

}  // namespace paver
