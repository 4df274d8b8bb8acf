#pragma once
// Whether a pavement is fit to use, in one word and a list of reasons: what the summary prints
// first and report.json carries as `verdict`. A pavement is ok when no pair violates the contact
// rule, no element crosses the boundary, the pattern is not torn, it is not mostly bare, and, as a
// jeweller judges it at its edges (issue 40), no bare spot is left and no rim is uneven.
#include "report/pavement_quality.h"

#include <nlohmann/json_fwd.hpp>

#include <optional>
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
// A place inside the margin where another stone of the spot size still fits (report/edge_quality.h).
// Judged for pave only (stones that touch, report/edge_quality.h): a pattern spaced wider has room
// between its elements by design.
inline bool has_bare_spots(const PavementQuality& q) {
  return q.edges.measured && q.edges.pave && q.edges.bare_spots > 0;
}
// A rim the design lays rows along whose metal, girdle to rim less the margin, has teeth: p95 > 0.3 d.
inline bool has_uneven_rim(const PavementQuality& q) {
  return q.edges.measured && q.edges.pave && q.edges.rim_samples > 0 && q.edges.rim_metal_p95 > kUnevenRim;
}

// Stones as ordered (issue 40): the median nearest-neighbour gap of pave at most this share of D
// beyond the gap asked (a band's closure widens it; the rest of the pass brings stones to contact).
inline constexpr double kGapOverAsked = 0.03;
// The median nearest-neighbour gap (surface units) of stones of the edges' size d: the ratios are
// centre distance over the radii summed. None where no stone size was measured.
inline std::optional<double> median_neighbour_gap(const PavementQuality& q) {
  if (!(q.edges.measured && q.edges.stone > 0 && q.elements > 1)) return std::nullopt;
  return (q.neighbor_ratio.median - 1) * q.edges.stone;
}
inline bool gap_as_asked(const PavementQuality& q) {
  const std::optional<double> median_gap = median_neighbour_gap(q);
  if (!q.edges.pave || !median_gap) return true;
  return *median_gap - q.gap <= kGapOverAsked * (q.edges.stone + q.gap);
}

// Rim metal p95 figures closer than this (in d) rank as even, and the fill decides.
inline constexpr double kRimEvenTie = 0.05;

struct Verdict {
  bool ok = true;
  std::vector<std::string> problems;  // each a sentence with its figures; empty when ok
};

Verdict judge_pavement(const PavementQuality& final_quality);

// Of two pavements of one surface tried for one design (topology auto, a band's annulus, its rows
// both ways): whether `candidate` is better than `incumbent`: fewer verdict problems of soundness
// (contact, crossings, torn, bare patches), then an even rim over an uneven one, then fewer bare
// spots (what the eye sees before it counts stones), then, where both are pave, the gap as asked
// (gap_as_asked) over a wider one and a lower rim metal p95 where both measure rims and differ by
// more than kRimEvenTie d, then a higher fill (elements over the ideal count at each one's own D).
// Equal: not better.
bool paves_better(const PavementQuality& candidate, const PavementQuality& incumbent);

nlohmann::json to_json(const Verdict& verdict);

}  // namespace paver
