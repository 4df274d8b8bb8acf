// Tests for engine/elements/element_proximity.cpp: find_collisions and nearest_neighbor_ratios,
// which use a spatial hash, give exactly what a plain all-pairs loop written here gives, on random
// element sets with mixed diameters, pairs placed exactly at the collision threshold and elements
// sharing a centre, at gap 0 and with a gap; and the rule itself is exact and strict
// (d < r_i + r_j + gap, no tolerance). nearest_clearances likewise against all pairs; a set of
// several parallel chunks (count_collisions too) as well, and the report's one search
// (measure_proximity) for all three.
#include "elements/element_proximity.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace paver {
namespace {

void add(Elements& e, glm::dvec3 centre, double diameter) {
  e.push_back(ElementKind::Vertex, int(e.size()), 0, {centre.x, centre.y}, centre, {0, 0, 1}, diameter,
              ShapeKind::Sphere);
}

double reach(const Elements& e, int i, int j) { return 0.5 * (e.diameter[i] + e.diameter[j]); }

// The contact rule, written out here, over every pair, with no spatial structure.
std::vector<Collision> all_pairs_collisions(const Elements& e, double gap) {
  std::vector<Collision> out;
  for (int i = 0; i < int(e.size()); ++i)
    for (int j = i + 1; j < int(e.size()); ++j) {
      const double d = glm::length(e.position[i] - e.position[j]);
      const double need = reach(e, i, j) + gap;
      if (d < need) out.push_back({i, j, d, 1 - d / need, d - reach(e, i, j)});
    }
  return out;  // already sorted by (i, j)
}

// min over j != i of d_ij - r_i - r_j; +inf for a lone element.
std::vector<double> all_pairs_clearances(const Elements& e) {
  std::vector<double> out(e.size(), std::numeric_limits<double>::infinity());
  for (int i = 0; i < int(e.size()); ++i)
    for (int j = 0; j < int(e.size()); ++j)
      if (j != i) out[i] = std::min(out[i], glm::length(e.position[i] - e.position[j]) - reach(e, i, j));
  return out;
}

// min over j != i of d_ij / (r_i + r_j); +inf for a lone element.
std::vector<double> all_pairs_ratios(const Elements& e) {
  std::vector<double> ratio(e.size(), std::numeric_limits<double>::infinity());
  for (int i = 0; i < int(e.size()); ++i)
    for (int j = 0; j < int(e.size()); ++j)
      if (j != i) ratio[i] = std::min(ratio[i], glm::length(e.position[i] - e.position[j]) / reach(e, i, j));
  return ratio;
}

// `n` elements in a box of side `side` (centred on `centre`), diameters drawn from a mix of small
// and large; then pairs put exactly at the required distance (radii + gap) along an axis and pairs
// on one centre.
Elements random_elements(std::mt19937& rng, int n, double side, glm::dvec3 centre, double gap) {
  std::uniform_real_distribution<double> coordinate(-0.5 * side, 0.5 * side);
  std::uniform_real_distribution<double> small(0.1, 0.5), large(0.8, 2.0);
  std::bernoulli_distribution is_large(0.3);
  Elements e;
  for (int i = 0; i < n; ++i)
    add(e, centre + glm::dvec3(coordinate(rng), coordinate(rng), coordinate(rng)), is_large(rng) ? large(rng) : small(rng));
  // Partners at exactly r_i + r_j + gap from an element (the distance the test's own loop
  // computes is the one that decides, so the pair lands on whichever side rounding puts it), one
  // ulp closer, and on the same centre.
  std::uniform_int_distribution<int> any(0, n - 1);
  for (int k = 0; k < 60; ++k) {
    const int i = any(rng);
    const double d = is_large(rng) ? large(rng) : small(rng);
    const double at = 0.5 * (e.diameter[i] + d) + gap;
    const glm::dvec3 axis = k % 3 == 0 ? glm::dvec3(1, 0, 0) : k % 3 == 1 ? glm::dvec3(0, -1, 0) : glm::dvec3(0, 0, 1);
    switch (k % 4) {
      case 0: add(e, e.position[i] + at * axis, d); break;
      case 1: add(e, e.position[i] + std::nextafter(at, 0.0) * axis, d); break;
      case 2: add(e, e.position[i], d); break;                         // coincident centres
      case 3: add(e, e.position[i] + 0.5 * at * axis, e.diameter[i]); break;
    }
  }
  return e;
}

// Per element, the search's value must be exactly the all-pairs one; `what` names the function.
void expect_same_per_element(const std::vector<double>& got, const std::vector<double>& want, const char* what) {
  ASSERT_EQ(got.size(), want.size());
  int wrong = 0;
  for (size_t i = 0; i < want.size(); ++i)
    if (got[i] != want[i] && ++wrong <= 10)
      ADD_FAILURE() << "element " << i << ": " << what << " gives " << got[i] << ", all pairs give " << want[i];
  EXPECT_EQ(wrong, 0) << "elements whose value differs from the all-pairs minimum";
}

void expect_same_ratios(const std::vector<double>& got, const std::vector<double>& want) {
  expect_same_per_element(got, want, "nearest_neighbor_ratios");
}

void expect_same_collisions(const std::vector<Collision>& got, const std::vector<Collision>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (size_t k = 0; k < want.size(); ++k) {
    EXPECT_EQ(got[k].i, want[k].i) << k;
    EXPECT_EQ(got[k].j, want[k].j) << k;
    EXPECT_EQ(got[k].distance, want[k].distance) << k;
    EXPECT_EQ(got[k].overlap, want[k].overlap) << k;
    EXPECT_EQ(got[k].clearance, want[k].clearance) << k;
  }
}

TEST(ElementProximityCollisions, MatchAllPairsOnRandomMixedSets) {
  std::mt19937 rng(20240611);
  // Dense (many collisions), medium, and far from the origin (negative and large hash cells).
  const struct {
    int n;
    double side;
    glm::dvec3 centre;
  } sets[] = {{3000, 14, {0, 0, 0}}, {3000, 30, {0, 0, 0}}, {2000, 20, {-1e4, 3e5, -77.5}}};
  for (const double gap : {0.0, 0.3}) {
    for (const auto& set : sets) {
      const Elements e = random_elements(rng, set.n, set.side, set.centre, gap);
      const std::vector<Collision> want = all_pairs_collisions(e, gap);
      ASSERT_GT(want.size(), 60u) << "the set should have collisions to find";
      expect_same_collisions(find_collisions(e, gap), want);
      expect_same_per_element(nearest_clearances(e), all_pairs_clearances(e), "nearest_clearances");
    }
  }
}

TEST(ElementProximityCollisions, ASetSearchedInManyParallelChunksGivesTheAllPairsResult) {
  // The searches split the elements into chunks of 4,096 searched in parallel: more than two
  // chunks here, so pairs across chunks, the join of their results and its order all count.
  std::mt19937 rng(20261126);
  const double gap = 0.1;
  const Elements e = random_elements(rng, 10000, 40, {3, -2, 1}, gap);
  const std::vector<Collision> want = all_pairs_collisions(e, gap);
  ASSERT_GT(want.size(), 1000u) << "the set should have collisions in every chunk";
  expect_same_collisions(find_collisions(e, gap), want);
  const CollisionTally tally = count_collisions(e, gap);
  EXPECT_EQ(tally.pairs, long(want.size()));
  double worst = 0;
  for (const Collision& c : want) worst = std::max(worst, c.overlap);
  EXPECT_EQ(tally.worst_overlap, worst);
  expect_same_per_element(nearest_clearances(e), all_pairs_clearances(e), "nearest_clearances");
  expect_same_ratios(nearest_neighbor_ratios(e), all_pairs_ratios(e));
}

TEST(ElementProximityCollisions, TheReportsOneSearchGivesTheAllPairsFigures) {
  // measure_proximity counts the collisions in its nearest-neighbour search's first pass when the
  // gap is at most the largest diameter (2.0: one element has it exactly), and in a search of its
  // own for a wider gap.
  std::mt19937 rng(20261127);
  for (const double gap : {0.0, 0.25, 2.0, 2.5}) {
    Elements e = random_elements(rng, 9000, 36, {-5, 1e3, 2}, gap);
    add(e, e.position[0] + glm::dvec3(0, 0, std::nextafter(0.5 * (e.diameter[0] + 2.0) + gap, 0.0)), 2.0);
    const std::vector<Collision> want = all_pairs_collisions(e, gap);
    ASSERT_GT(want.size(), 1000u) << "the set should have many collisions, across its three chunks";
    const ProximityFigures got = measure_proximity(e, gap);
    EXPECT_EQ(got.collisions.pairs, long(want.size())) << "gap " << gap;
    double worst = 0;
    for (const Collision& c : want) worst = std::max(worst, c.overlap);
    EXPECT_EQ(got.collisions.worst_overlap, worst) << "gap " << gap;
    expect_same_per_element(got.clearances, all_pairs_clearances(e), "measure_proximity's clearances");
    expect_same_per_element(got.neighbor_ratios, all_pairs_ratios(e), "measure_proximity's ratios (gap 0)");
  }
}

TEST(ElementProximityCollisions, TheRuleIsExactWithNoTolerance) {
  // Diameters 2 and 2: touching at 2; with gap 0.5 they need 2.5. Exactly there is no violation;
  // one ulp closer is one, and a pair 0.5% short (which a forgiving rule would pass) is one.
  for (const double gap : {0.0, 0.5}) {
    const double need = 2 + gap;
    Elements at;
    add(at, {0, 0, 0}, 2);
    add(at, {need, 0, 0}, 2);
    EXPECT_TRUE(find_collisions(at, gap).empty()) << "a pair exactly at r_i + r_j + gap is fine, gap " << gap;

    for (const double d : {std::nextafter(need, 0.0), 0.995 * need}) {
      Elements below;
      add(below, {0, 0, 0}, 2);
      add(below, {d, 0, 0}, 2);
      const std::vector<Collision> c = find_collisions(below, gap);
      ASSERT_EQ(c.size(), 1u) << "d " << d << ", gap " << gap;
      EXPECT_EQ(c[0].i, 0);
      EXPECT_EQ(c[0].j, 1);
      EXPECT_DOUBLE_EQ(c[0].overlap, 1 - d / need);
      EXPECT_DOUBLE_EQ(c[0].clearance, d - 2);
    }
  }
}

TEST(ElementProximityCollisions, CoincidentCentresOverlapFully) {
  Elements e;
  add(e, {5, 5, 5}, 1);
  add(e, {5, 5, 5}, 0.25);
  add(e, {5, 5, 5}, 3);
  const std::vector<Collision> c = find_collisions(e, 0);
  ASSERT_EQ(c.size(), 3u);
  const int pairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(c[k].i, pairs[k][0]);
    EXPECT_EQ(c[k].j, pairs[k][1]);
    EXPECT_EQ(c[k].distance, 0);
    EXPECT_EQ(c[k].overlap, 1);
  }
  for (double r : nearest_neighbor_ratios(e)) EXPECT_EQ(r, 0);
}

TEST(ElementProximityCollisions, EmptyAndSingleSetsHaveNone) {
  Elements e;
  EXPECT_TRUE(find_collisions(e, 0).empty());
  EXPECT_TRUE(nearest_neighbor_ratios(e).empty());
  add(e, {1, 2, 3}, 1);
  EXPECT_TRUE(find_collisions(e, 0).empty());
  ASSERT_EQ(nearest_neighbor_ratios(e).size(), 1u);
  EXPECT_EQ(nearest_neighbor_ratios(e)[0], std::numeric_limits<double>::infinity());
}

TEST(ElementProximityNeighbours, MatchAllPairsOnRandomMixedSets) {
  std::mt19937 rng(99);
  // Dense sets: every element has a neighbour within twice its reach.
  for (double side : {14.0, 20.0}) {
    const Elements e = random_elements(rng, 3000, side, {0, 0, 0}, 0.0);
    const std::vector<double> want = all_pairs_ratios(e);
    expect_same_ratios(nearest_neighbor_ratios(e), want);
  }
}

TEST(ElementProximityNeighbours, LoneElementsFallBackToAllPairs) {
  // Three elements far apart (well beyond the search cells): each still gets its true ratio.
  Elements e;
  add(e, {0, 0, 0}, 1);
  add(e, {100, 0, 0}, 1);
  add(e, {0, 250, 0}, 3);
  const std::vector<double> r = nearest_neighbor_ratios(e);
  EXPECT_DOUBLE_EQ(r[0], 100.0);
  EXPECT_DOUBLE_EQ(r[1], 100.0);
  EXPECT_DOUBLE_EQ(r[2], 250.0 / 2);
  expect_same_ratios(r, all_pairs_ratios(e));
}

// The search looks at cells two largest diameters wide; an element whose only element in reach is
// small (a large ratio) must still find a larger element just outside the cells whose ratio is
// smaller (a bug found by this test: the search used to trust any neighbour it found).
TEST(ElementProximityNeighbours, LooseMixedSetsMatchAllPairs) {
  // Largest diameter 1 -> cells 2 wide. A (0.1) and B (0.1) are 1.8 apart in one cell: ratio 18.
  // C (1) is 4.5 from A, two cells up: ratio 4.5 / 0.55 = 8.18 for A, 4.85 / 0.55 = 8.81 for B.
  Elements e;
  add(e, {0.1, 0.1, 0.1}, 0.1);
  add(e, {1.9, 0.1, 0.1}, 0.1);
  add(e, {0.1, 4.6, 0.1}, 1);
  const std::vector<double> want = all_pairs_ratios(e);
  EXPECT_NEAR(want[0], 4.5 / 0.55, 1e-12);
  expect_same_ratios(nearest_neighbor_ratios(e), want);

  // The same on a random loose set (elements a few diameters apart, diameters 0.1 to 2).
  std::mt19937 rng(5);
  const Elements loose = random_elements(rng, 2000, 60, {0, 0, 0}, 0.0);
  expect_same_ratios(nearest_neighbor_ratios(loose), all_pairs_ratios(loose));
  expect_same_per_element(nearest_clearances(loose), all_pairs_clearances(loose), "nearest_clearances");
}

}  // namespace
}  // namespace paver

namespace paver {
namespace {

// Tiny elements far apart on a part far from the origin (element scale 1e-9, which used to hang:
// the grid's cells were a billionth of the part and their indices overflowed, and every element
// fell back to a scan of all others). Exact ratios, and a collision search that finds none.
TEST(ElementProximityNeighbours, TinyElementsFarFromTheOriginAreExact) {
  Elements e;
  const glm::dvec3 origin(3e7, -2e7, 5e6);
  for (int y = 0; y < 120; ++y)
    for (int x = 0; x < 120; ++x) add(e, origin + glm::dvec3(2.0 * x + (y % 2), 1.5 * y, 0.25 * ((x * y) % 3)), 1e-9);
  const std::vector<double> r = nearest_neighbor_ratios(e);
  EXPECT_TRUE(find_collisions(e, 0).empty());
  // Spot-check against all pairs (the whole set would take the test a while).
  for (int i : {0, 1, 119, 7000, 14399}) {
    double want = std::numeric_limits<double>::infinity();
    for (int j = 0; j < int(e.size()); ++j)
      if (j != i) want = std::min(want, glm::length(e.position[i] - e.position[j]) / reach(e, i, j));
    EXPECT_DOUBLE_EQ(r[i], want) << "element " << i;
  }
}

}  // namespace
}  // namespace paver
