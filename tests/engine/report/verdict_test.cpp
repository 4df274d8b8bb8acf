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

}  // namespace
}  // namespace paver
