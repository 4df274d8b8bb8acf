#include "pattern/contact_packing.h"

#include "map/lifting.h"
#include "surface_maps.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <random>

namespace paver {
namespace {

// Random points inside the square's map (a similarity of it, maybe rotated): within 0.64 of the
// map box's half-size from its centre, which a square turned any way contains (0.71).
std::vector<glm::dvec2> random_points(const SurfaceMap& map, int count, unsigned seed) {
  glm::dvec2 lo(1e300), hi(-1e300);
  for (const glm::dvec2& p : map.uv) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const glm::dvec2 centre = 0.5 * (lo + hi);
  const double half = 0.5 * std::min(hi.x - lo.x, hi.y - lo.y);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> t(-0.45, 0.45);
  std::vector<glm::dvec2> uv(count);
  for (glm::dvec2& p : uv) p = centre + half * glm::dvec2(t(rng), t(rng));
  return uv;
}

// Every pair, independently of the packing's own pair lists.
double closest_pair(const std::vector<glm::dvec3>& x) {
  double best = 1e300;
  for (size_t i = 0; i < x.size(); ++i)
    for (size_t j = i + 1; j < x.size(); ++j) best = std::min(best, glm::length(x[i] - x[j]));
  return best;
}

TEST(ContactPacking, ALooseCrowdSpreadsUntilNoPairIsWithinContact) {
  const SurfaceMap& map = test::flat_unit_square();
  std::vector<glm::dvec2> uv = random_points(map, 150, 7);
  ContactPackingOptions options;
  options.contact = 0.06;  // 150 discs of 0.06 fill about 45% of the square's hexagonal packing
  options.margin = 0.03;
  ASSERT_LT(closest_pair(test::lifted_positions(map, uv)), 0.5 * options.contact);  // it starts crowded
  const ContactPackingReport report = pack_by_contact(map, uv, options);
  EXPECT_EQ(report.overlapping_pairs, 0);
  EXPECT_EQ(report.removed, 0);
  ASSERT_EQ(uv.size(), 150u);
  const std::vector<glm::dvec3> x = test::lifted_positions(map, uv);
  EXPECT_GE(closest_pair(x), options.contact * (1 - kSettledOverlap));
  for (const glm::dvec3& p : x) EXPECT_GE(std::min({p.x, p.y, 1 - p.x, 1 - p.y}), options.margin * 0.999);
}

TEST(ContactPacking, AnOverfullSquareLosesItsJammedParticlesAFewPerRound) {
  const SurfaceMap& map = test::flat_unit_square();
  // 400 discs of 0.06 need 1.25 times the square (less its margin) even packed hexagonally.
  std::vector<glm::dvec2> uv = random_points(map, 400, 11);
  ContactPackingOptions options;
  options.contact = 0.06;
  options.margin = 0.03;
  options.iterations = 300;
  options.rounds = 60;
  options.remove_share = 0.02;
  const ContactPackingReport report = pack_by_contact(map, uv, options);
  EXPECT_EQ(report.overlapping_pairs, 0);
  EXPECT_GT(report.removed, 0);
  EXPECT_EQ(int(uv.size()), 400 - report.removed);
  EXPECT_GE(closest_pair(test::lifted_positions(map, uv)), options.contact * (1 - kSettledOverlap));
  // No more removed than jamming asks: at least 75% of the hexagonal packing's count stays
  // (the square less its margin, 0.94 x 0.94, over sqrt(3)/2 x 0.06^2 per disc: about 283).
  EXPECT_GT(double(uv.size()), 0.75 * 0.94 * 0.94 / (std::sqrt(3.0) / 2 * 0.06 * 0.06));
}

}  // namespace
}  // namespace paver
