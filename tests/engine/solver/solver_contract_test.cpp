// Tests for the period helpers of engine/solver/solver_contract.h (wrap_position, nearest_image):
// the fast paths (at most one period out) and the division for points farther away give the same
// copy, checked against a plain double-precision rule.
#include "solver/solver_contract.h"

#include <gtest/gtest.h>

#include <glm/vec2.hpp>

#include <cmath>

namespace paver {
namespace {

constexpr float kPeriod = 12.5f;
constexpr float kOrigin = -3.25f;

TEST(SolverContract, WrapPositionPutsEveryPointInOnePeriod) {
  for (float u = -80.0f; u <= 80.0f; u += 0.37f) {
    const glm::vec2 w = wrap_position(kPeriod, kOrigin, glm::vec2(u, 2.0f));
    EXPECT_GE(w.x, kOrigin) << "u " << u;
    EXPECT_LT(w.x, kOrigin + kPeriod) << "u " << u;
    EXPECT_EQ(w.y, 2.0f);
    // A whole number of periods away from where it started.
    const double turns = (double(u) - w.x) / kPeriod;
    EXPECT_NEAR(turns, std::round(turns), 1e-4) << "u " << u;
  }
}

TEST(SolverContract, NearestImageIsTheCopyClosestToTheReference) {
  const glm::vec2 near(4.0f, -1.0f);
  for (float u = -90.0f; u <= 90.0f; u += 0.41f) {
    const glm::vec2 image = nearest_image(kPeriod, glm::vec2(u, 7.0f), near);
    EXPECT_LE(std::abs(image.x - near.x), 0.5f * kPeriod + 1e-4f) << "u " << u;
    EXPECT_EQ(image.y, 7.0f);
    const double turns = (double(u) - image.x) / kPeriod;
    EXPECT_NEAR(turns, std::round(turns), 1e-4) << "u " << u;
  }
}

TEST(SolverContract, OneCopyAwayIsExactlyOnePeriodOff) {
  // The positions a solver step sees: wrapped, so the other end is at most one period off.
  EXPECT_EQ(nearest_image(kPeriod, glm::vec2(kOrigin + 0.5f, 0.0f), glm::vec2(kOrigin + kPeriod - 0.5f, 0.0f)).x,
            kOrigin + 0.5f + kPeriod);
  EXPECT_EQ(wrap_position(kPeriod, kOrigin, glm::vec2(kOrigin - 0.25f, 0.0f)).x, kOrigin - 0.25f + kPeriod);
  EXPECT_EQ(wrap_position(kPeriod, kOrigin, glm::vec2(kOrigin + kPeriod, 0.0f)).x, kOrigin);
}

TEST(SolverContract, NoPeriodLeavesPointsAlone) {
  const glm::vec2 p(123.0f, -4.0f);
  EXPECT_EQ(wrap_position(0.0f, 0.0f, p), p);
  EXPECT_EQ(nearest_image(0.0f, p, glm::vec2(-500.0f, 0.0f)), p);
}

}  // namespace
}  // namespace paver
