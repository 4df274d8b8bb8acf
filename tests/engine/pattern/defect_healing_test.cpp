#include "pattern/defect_healing.h"

#include "map/lifting.h"
#include "pattern/contact_packing.h"
#include "pattern/surface_triangulation.h"
#include "surface_maps.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <atomic>
#include <random>

namespace paver {
namespace {

// Interior (kDepth from the square's sides) particles that are not 6-valent in the surface
// triangulation of all of them: the count the healing reports, made here from the particles alone.
constexpr double kContact = 0.05, kMargin = 0.03, kDepth = 2 * kContact;
int interior_defects(const SurfaceMap& map, const std::vector<glm::dvec2>& uv) {
  const std::vector<glm::dvec3> x = test::lifted_positions(map, uv);
  std::vector<int> valence(uv.size(), 0);
  std::vector<std::pair<int, int>> edges;
  for (const glm::ivec3& t : triangulate_surface_points(uv, x, 2.5 * kContact))
    for (int k = 0; k < 3; ++k) edges.push_back(std::minmax(t[k], t[(k + 1) % 3]));
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  for (const auto& [a, b] : edges) ++valence[a], ++valence[b];
  int defects = 0;
  for (size_t i = 0; i < x.size(); ++i)
    defects += std::min({x[i].x, x[i].y, 1 - x[i].x, 1 - x[i].y}) >= kDepth && valence[i] != 6;
  return defects;
}

// A crowd packed to contact from random points at 85% of the hexagonal packing's count: jammed,
// with the dislocations that packing freezes in.
std::vector<glm::dvec2> jammed_crowd(const SurfaceMap& map) {
  glm::dvec2 lo(1e300), hi(-1e300);
  for (const glm::dvec2& p : map.uv) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const glm::dvec2 centre = 0.5 * (lo + hi);
  const double half = 0.5 * std::min(hi.x - lo.x, hi.y - lo.y);
  const double usable = 1 - 2 * kMargin;
  const int count = int(0.85 * usable * usable / (std::sqrt(3.0) / 2 * kContact * kContact));
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> t(-0.45, 0.45);
  std::vector<glm::dvec2> uv(count);
  for (glm::dvec2& p : uv) p = centre + half * glm::dvec2(t(rng), t(rng));
  ContactPackingOptions packing;
  packing.contact = kContact;
  packing.margin = kMargin;
  packing.iterations = 2000;
  packing.rounds = 12;
  pack_by_contact(map, uv, packing);
  return uv;
}

DefectHealingOptions healing_options() {
  DefectHealingOptions options;
  options.spacing = kContact;
  options.contact = kContact;
  options.margin = kMargin;
  options.interior_depth = kDepth;
  return options;
}

TEST(DefectHealing, AJammedCrowdKeepsItsCountAndContactWithFewerDefects) {
  const SurfaceMap& map = test::flat_unit_square();
  const std::vector<glm::dvec2> packed = jammed_crowd(map);
  std::vector<glm::dvec2> uv = packed;
  const DefectHealingReport report = heal_defects(map, uv, healing_options());

  EXPECT_EQ(uv.size(), packed.size());
  EXPECT_EQ(report.defects_before, interior_defects(map, packed));
  EXPECT_EQ(report.defects_after, interior_defects(map, uv));
  ASSERT_GT(report.defects_before, 20) << "the crowd should start disordered";
  EXPECT_LT(report.defects_after, 0.9 * report.defects_before);
  EXPECT_GT(report.moved, 0);
  EXPECT_LE(report.moved, report.tries);
  // Every pair, independently of the healing's own neighbourhoods: no pair under the contact
  // the packing settles at, and every particle its margin from the sides.
  const std::vector<glm::dvec3> x = test::lifted_positions(map, uv);
  for (size_t i = 0; i < x.size(); ++i) {
    EXPECT_GE(std::min({x[i].x, x[i].y, 1 - x[i].x, 1 - x[i].y}), kMargin * (1 - 1e-9)) << i;
    for (size_t j = i + 1; j < x.size(); ++j)
      ASSERT_GE(glm::length(x[i] - x[j]), kContact * (1 - kSettledOverlap)) << i << " " << j;
  }
}

TEST(DefectHealing, TheSameCrowdHealsTheSameWay) {
  const SurfaceMap& map = test::flat_unit_square();
  std::vector<glm::dvec2> first = jammed_crowd(map), second = first;
  heal_defects(map, first, healing_options());
  heal_defects(map, second, healing_options());
  EXPECT_EQ(first, second);
}

TEST(DefectHealing, AStopLeavesTheParticlesAsTheyWere) {
  const SurfaceMap& map = test::flat_unit_square();
  const std::vector<glm::dvec2> packed = jammed_crowd(map);
  std::vector<glm::dvec2> uv = packed;
  const std::atomic<bool> stop{true};
  const DefectHealingReport report = heal_defects(map, uv, healing_options(), &stop);
  EXPECT_EQ(report.tries, 0);
  EXPECT_EQ(uv, packed);
}

}  // namespace
}  // namespace paver
