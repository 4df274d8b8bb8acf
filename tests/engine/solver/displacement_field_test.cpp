// Tests for engine/solver/displacement_field.cpp: the field that carries a coarse relaxation onto
// a finer lattice. Samples in, interpolated values out, including where no sample fell.
#include "solver/displacement_field.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace paver {
namespace {

TEST(DisplacementField, AConstantFieldComesBackExactlyEverywhere) {
  DisplacementField field({0, 0}, {10, 5}, 0.5);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> x(2, 4), y(1, 2);  // samples in one corner only
  for (int i = 0; i < 200; ++i) field.add({x(rng), y(rng)}, {0.25, -0.5});
  field.finish();
  for (const glm::dvec2 p : {glm::dvec2(3, 1.5), glm::dvec2(9.5, 4.5), glm::dvec2(0, 0), glm::dvec2(-3, 20)}) {
    EXPECT_NEAR(field.at(p).x, 0.25, 1e-12) << p.x << ", " << p.y;
    EXPECT_NEAR(field.at(p).y, -0.5, 1e-12) << p.x << ", " << p.y;
  }
}

TEST(DisplacementField, ALinearFieldSampledDenselyIsFollowedToWithinACellsChange) {
  const double cell = 0.25;
  DisplacementField field({0, 0}, {4, 4}, cell);
  const auto linear = [](glm::dvec2 p) { return glm::dvec2(0.1 * p.x - 0.05 * p.y, 0.02 * p.y); };
  for (double u = 0.05; u < 4; u += 0.1)
    for (double v = 0.05; v < 4; v += 0.1) field.add({u, v}, linear({u, v}));
  field.finish();
  // The field changes by at most 0.15 per cell: what the tent weights blur.
  for (double u = 0.3; u < 3.7; u += 0.37)
    for (double v = 0.3; v < 3.7; v += 0.41) {
      EXPECT_NEAR(field.at({u, v}).x, linear({u, v}).x, 0.15 * cell);
      EXPECT_NEAR(field.at({u, v}).y, linear({u, v}).y, 0.15 * cell);
    }
}

TEST(DisplacementField, NodesWithoutSamplesTakeTheirNeighboursValues) {
  DisplacementField field({0, 0}, {10, 1}, 1);
  field.add({0.5, 0.5}, {1, 0});  // one sample at each end of a long strip
  field.add({9.5, 0.5}, {3, 0});
  field.finish();
  // Grown ring by ring from both ends: the middle lies between the two values, each end at its own.
  EXPECT_NEAR(field.at({0.5, 0.5}).x, 1, 1e-12);
  EXPECT_NEAR(field.at({9.5, 0.5}).x, 3, 1e-12);
  const double middle = field.at({5, 0.5}).x;
  EXPECT_GT(middle, 1);
  EXPECT_LT(middle, 3);
}

TEST(DisplacementField, AFieldWithoutSamplesIsZero) {
  DisplacementField field({-1, -1}, {1, 1}, 0.1);
  field.finish();
  EXPECT_EQ(field.at({0, 0}), glm::dvec2(0));
}

}  // namespace
}  // namespace paver
