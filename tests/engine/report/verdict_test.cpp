// Tests for engine/report/verdict.cpp: the verdict lists each problem in words a user can read,
// with its count in the right number ("1 pair is", "2 pairs are").
#include "report/verdict.h"

#include "report/pavement_quality.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace paver {
namespace {

PavementQuality sound() {
  PavementQuality q;
  q.elements = 100;
  q.fill = 0.95;
  return q;
}

TEST(Verdict, ASoundPavementIsOk) {
  const Verdict v = judge_pavement(sound());
  EXPECT_TRUE(v.ok);
  EXPECT_TRUE(v.problems.empty());
}

TEST(Verdict, CountsReadInTheRightNumber) {
  PavementQuality q = sound();
  q.contact_violations = 1;
  q.min_clearance = -0.01;
  q.boundary_crossings = 1;
  Verdict v = judge_pavement(q);
  EXPECT_FALSE(v.ok);
  ASSERT_EQ(v.problems.size(), 2u);
  EXPECT_EQ(v.problems[0].rfind("1 pair is closer than their radii plus the gap", 0), 0u) << v.problems[0];
  EXPECT_EQ(v.problems[1], "1 element crosses the surface boundary");

  q.contact_violations = 2;
  q.boundary_crossings = 3;
  q.margin = 0.5;
  v = judge_pavement(q);
  ASSERT_EQ(v.problems.size(), 2u);
  EXPECT_EQ(v.problems[0].rfind("2 pairs are closer", 0), 0u) << v.problems[0];
  EXPECT_EQ(v.problems[1], "3 elements cross the surface boundary or its margin of 0.5");
}

// A star-shaped disk (2,000 rim vertices) was "ok" with fill 0.000: a fill that could not be
// measured passed the rule it fails. The verdict can never be ok under its own threshold.
TEST(Verdict, NeverOkWithTheFillUnderItsThreshold) {
  for (const double fill : {0.0, 1e-6, 0.5, kBareFill - 1e-9, std::nan("")}) {
    PavementQuality q = sound();
    q.fill = fill;
    const Verdict v = judge_pavement(q);
    EXPECT_FALSE(v.ok) << fill;
    ASSERT_EQ(v.problems.size(), 1u) << fill;
    EXPECT_NE(v.problems[0].find(fill > 0 ? "bare patches" : "could not be measured"), std::string::npos) << v.problems[0];
  }
  PavementQuality q = sound();
  q.fill = kBareFill;
  EXPECT_TRUE(judge_pavement(q).ok);
  q.elements = 0;
  q.fill = 0;
  EXPECT_EQ(judge_pavement(q).problems, (std::vector<std::string>{"no elements were placed"}));
}

// Issue 40: pave is judged at its edges as the eye does. A bare spot and an uneven rim are each a
// problem with its figures and where it is; for a pattern that is not pave neither is.
TEST(Verdict, PaveWithABareSpotOrAnUnevenRimIsNotOk) {
  PavementQuality q = sound();
  q.edges.measured = true;
  q.edges.pave = true;
  q.edges.spot_stone = 1.2;
  q.edges.largest_fit = 1.3;
  q.edges.bare_spots = 3;
  q.edges.spots = {BareSpot{{1, 2, 3}, {0, 0}, 0, 1.3, 1.2}};
  q.edges.rim_samples = 500;
  q.edges.rim_metal_p95 = 0.31;
  q.edges.rim_metal_max = 0.6;
  Verdict v = judge_pavement(q);
  EXPECT_FALSE(v.ok);
  ASSERT_EQ(v.problems.size(), 2u);
  EXPECT_EQ(v.problems[0].rfind("3 bare spots where a stone of 1.2 still fits (the widest fits 1.3, at 1, 2, 3", 0), 0u)
      << v.problems[0];
  EXPECT_EQ(v.problems[1].rfind("an uneven rim: ", 0), 0u) << v.problems[1];
  EXPECT_NE(v.problems[1].find("0.31 d at p95 (max 0.60 d"), std::string::npos) << v.problems[1];

  q.edges.bare_spots = 0;
  q.edges.spots.clear();
  q.edges.rim_metal_p95 = 0.3;  // at the bound: even
  EXPECT_TRUE(judge_pavement(q).ok) << judge_pavement(q).problems.front();
  q.edges.bare_spots = 1;
  q.edges.rim_metal_p95 = 0.9;
  q.edges.pave = false;  // a honeycomb, a grid, spheres spaced wider: judged by the fill
  EXPECT_TRUE(judge_pavement(q).ok);
}

// The one ranking: soundness, then an even rim, then fewer bare spots, then the rims' evenness
// beyond a tie, then the fill, which alone ranked pavements before.
TEST(Verdict, TheBetterPavementHasFewerSpotsBeforeMoreStones) {
  PavementQuality spotless = sound(), spotted = sound();
  for (PavementQuality* q : {&spotless, &spotted}) q->edges.measured = q->edges.pave = true;
  spotted.edges.bare_spots = 4;
  spotted.fill = 1.1;  // more stones
  EXPECT_TRUE(paves_better(spotless, spotted));
  EXPECT_FALSE(paves_better(spotted, spotless));
  // A torn lattice with no spot loses to a sound pattern with one.
  PavementQuality torn = spotless;
  torn.spring_deviation_p95 = 0.7;
  spotted.edges.bare_spots = 1;
  EXPECT_TRUE(paves_better(spotted, torn));
  // An uneven rim loses to an even one with more spots.
  PavementQuality ragged = spotless;
  ragged.edges.rim_samples = spotted.edges.rim_samples = 100;
  ragged.edges.rim_metal_p95 = 0.5;
  spotted.edges.rim_metal_p95 = 0.2;
  EXPECT_TRUE(paves_better(spotted, ragged));
  // Even rims within the tie: the fill decides.
  PavementQuality a = spotless, b = spotless;
  a.edges.rim_samples = b.edges.rim_samples = 100;
  a.edges.rim_metal_p95 = 0.20, b.edges.rim_metal_p95 = 0.22, a.fill = 0.95, b.fill = 0.97;
  EXPECT_TRUE(paves_better(b, a));
  b.edges.rim_metal_p95 = 0.29;
  EXPECT_TRUE(paves_better(a, b)) << "0.09 d more metal at the rims outweighs the fill";
  // Not pave: spots do not rank.
  spotless.edges.pave = spotted.edges.pave = false;
  spotted.edges.bare_spots = 9;
  spotted.edges.rim_samples = spotless.edges.rim_samples = 0;
  EXPECT_TRUE(paves_better(spotted, spotless));
}

}  // namespace
}  // namespace paver
