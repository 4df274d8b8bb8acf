// Tests for engine/elements/element_frame.cpp: for any normal the frame (t, b, n) is orthonormal
// and right-handed (t x b = n) with n the normalised input: random directions of random lengths,
// the poles (+Z gives the identity, -Z the half turn about X), directions just off -Z and +Z, the
// equator; a zero or non-finite normal leaves the element upright; the frame changes smoothly near
// the poles; and place_shape_vertex puts a shape's axes along t, b and n.
#include "elements/element_frame.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace paver {
namespace {

std::string text(glm::dvec3 v) {
  std::ostringstream s;
  s.precision(17);
  s << "(" << v.x << ", " << v.y << ", " << v.z << ")";
  return s.str();
}

// Orthonormal, right-handed, n along the input.
::testing::AssertionResult is_frame_of(const ElementFrame& f, glm::dvec3 normal, double tolerance = 1e-12) {
  const glm::dvec3 want = normal / glm::length(normal);
  const struct {
    double got, want;
    const char* what;
  } checks[] = {{glm::length(f.t), 1, "|t|"},
                {glm::length(f.b), 1, "|b|"},
                {glm::length(f.n), 1, "|n|"},
                {glm::dot(f.t, f.b), 0, "t.b"},
                {glm::dot(f.t, f.n), 0, "t.n"},
                {glm::dot(f.b, f.n), 0, "b.n"},
                {glm::length(glm::cross(f.t, f.b) - f.n), 0, "|t x b - n|"},
                {glm::length(f.n - want), 0, "|n - normal / |normal||"}};
  for (const auto& c : checks)
    if (!(std::abs(c.got - c.want) <= tolerance))
      return ::testing::AssertionFailure() << "normal " << text(normal) << ": " << c.what << " = " << c.got
                                           << ", not " << c.want << " (t " << text(f.t) << ", b " << text(f.b)
                                           << ", n " << text(f.n) << ")";
  return ::testing::AssertionSuccess();
}

void expect_frame(const ElementFrame& f, glm::dvec3 t, glm::dvec3 b, glm::dvec3 n, const std::string& what) {
  EXPECT_EQ(f.t, t) << what << ": t " << text(f.t);
  EXPECT_EQ(f.b, b) << what << ": b " << text(f.b);
  EXPECT_EQ(f.n, n) << what << ": n " << text(f.n);
}

TEST(ElementFrame, RandomNormalsGiveRightHandedOrthonormalFrames) {
  std::mt19937 rng(42);
  std::normal_distribution<double> gauss;
  std::uniform_real_distribution<double> log_length(-3, 3);
  for (int k = 0; k < 20000; ++k) {
    const glm::dvec3 direction = glm::normalize(glm::dvec3(gauss(rng), gauss(rng), gauss(rng)));
    const glm::dvec3 normal = std::pow(10.0, log_length(rng)) * direction;
    ASSERT_TRUE(is_frame_of(element_frame(normal), normal));
  }
}

TEST(ElementFrame, PolesEquatorAndNearPoles) {
  const std::vector<glm::dvec3> normals = {
      {0, 0, -1}, {0, 0, 1}, {0, 0, -3}, {0, 0, 0.25},
      // just off -Z: the divisor 1 + |n.z| stays near 2, nothing blows up
      {1e-9, 0, -1}, {0, -1e-12, -1}, {1e-5, 1e-5, -1}, {-1e-16, 3e-17, -1}, {1e-300, 0, -1}, {0.01, -0.02, -1},
      // just off +Z
      {1e-9, 0, 1}, {0, -1e-12, 1}, {-1e-5, 1e-5, 1}, {1e-300, 1e-300, 1},
      // the equator, where the two rules meet, and both signs of zero
      {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {1, 1, 0}, {-3, 4, 0}, {1, 0, -0.0}, {0, 1, 1e-17}, {0, 1, -1e-17}};
  for (const glm::dvec3& normal : normals) EXPECT_TRUE(is_frame_of(element_frame(normal), normal));
}

TEST(ElementFrame, PlusZIsTheIdentityAndMinusZAHalfTurnAboutX) {
  expect_frame(element_frame({0, 0, 1}), {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, "+Z");
  expect_frame(element_frame({0, 0, 7.5}), {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, "7.5 Z");
  expect_frame(element_frame({0, 0, -1}), {1, 0, 0}, {0, -1, 0}, {0, 0, -1}, "-Z");
  expect_frame(element_frame({0, 0, -0.5}), {1, 0, 0}, {0, -1, 0}, {0, 0, -1}, "-0.5 Z");
}

TEST(ElementFrame, ZeroOrNonFiniteNormalsLeaveTheElementUpright) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (glm::dvec3 normal : {glm::dvec3(0, 0, 0), glm::dvec3(-0.0, 0, -0.0), glm::dvec3(nan, 0, 1), glm::dvec3(0, nan, 0),
                            glm::dvec3(0, 0, nan), glm::dvec3(nan, nan, nan), glm::dvec3(inf, 0, 0),
                            glm::dvec3(0, -inf, 1), glm::dvec3(1, 2, -inf), glm::dvec3(inf, nan, 0)})
    expect_frame(element_frame(normal), {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, "normal " + text(normal));
}

TEST(ElementFrame, ChangesSmoothlyNearThePoles) {
  // Within each hemisphere the rule is smooth: a normal 1e-7 off a pole gives a frame within about
  // 1e-7 of the pole's (no flip about n, as an arbitrary "any perpendicular" rule could give).
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> angle(0, 2 * 3.141592653589793);
  for (double z : {1.0, -1.0}) {
    const ElementFrame pole = element_frame({0, 0, z});
    for (int k = 0; k < 100; ++k) {
      const double a = angle(rng);
      const ElementFrame f = element_frame({1e-7 * std::cos(a), 1e-7 * std::sin(a), z});
      EXPECT_LT(glm::length(f.t - pole.t), 3e-7) << "z " << z << " angle " << a;
      EXPECT_LT(glm::length(f.b - pole.b), 3e-7) << "z " << z << " angle " << a;
    }
  }
}

TEST(ElementFrame, PlacesAShapesAxesAlongTheFrame) {
  const glm::dvec3 normal(0.3, -0.4, -0.2), centre(10, -20, 5);
  const double diameter = 2.5;
  const ElementFrame f = element_frame(normal);
  ASSERT_TRUE(is_frame_of(f, normal));
  auto near = [](glm::dvec3 a, glm::dvec3 b) { return glm::length(a - b) < 1e-12; };
  EXPECT_TRUE(near(place_shape_vertex(f, centre, diameter, {0, 0, 0}), centre));
  EXPECT_TRUE(near(place_shape_vertex(f, centre, diameter, {1, 0, 0}), centre + diameter * f.t));
  EXPECT_TRUE(near(place_shape_vertex(f, centre, diameter, {0, 1, 0}), centre + diameter * f.b));
  EXPECT_TRUE(near(place_shape_vertex(f, centre, diameter, {0, 0, 0.5}), centre + 0.5 * diameter * glm::normalize(normal)));
  // A triangle counter-clockwise seen from +Z faces along n once placed.
  const glm::dvec3 p = place_shape_vertex(f, centre, diameter, {0, 0, 0});
  const glm::dvec3 q = place_shape_vertex(f, centre, diameter, {1, 0, 0});
  const glm::dvec3 r = place_shape_vertex(f, centre, diameter, {0, 1, 0});
  EXPECT_GT(glm::dot(glm::cross(q - p, r - p), normal), 0);
}

// A bug found by this test: glm::length's square under- or overflowed, leaving such normals upright.
TEST(ElementFrame, NormalsOfExtremeLengthKeepTheirDirection) {
  // "normal need not be unit": any finite non-zero normal should give its own direction.
  for (glm::dvec3 normal : {glm::dvec3(1e-200, 0, 0), glm::dvec3(0, 3e-170, -4e-170), glm::dvec3(1e-160, 0, 1e-160),
                            glm::dvec3(1e200, 1e200, 0), glm::dvec3(0, -1e300, 1e300), glm::dvec3(1e-310, 0, 0)})
    EXPECT_TRUE(is_frame_of(element_frame(normal), normal / std::max({std::abs(normal.x), std::abs(normal.y), std::abs(normal.z)})))
        << "normal " << text(normal);
}

}  // namespace
}  // namespace paver
