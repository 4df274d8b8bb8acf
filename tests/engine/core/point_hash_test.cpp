// Tests for engine/core/point_hash.h: the open-addressing hash must find every point within
// one cell width, for points bucketed at construction and inserted later (through its growth),
// far from the origin and at negative cells alike.
#include "core/point_hash.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <random>
#include <set>
#include <vector>

namespace paver {
namespace {

TEST(PointHash, FindsEveryPointWithinOneCellLikeABruteForceLoop) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-5, 5);
  const glm::dvec3 far(1e5, -2e5, 3e5);  // a part far from the origin
  std::vector<glm::dvec3> points(3000);
  for (auto& p : points) p = far + glm::dvec3(u(rng), u(rng), 0.1 * u(rng));
  const CellGrid grid(far - glm::dvec3(6), far + glm::dvec3(6), 0.4);
  // Half bucketed at once, half inserted one by one (the table grows several times on the way).
  std::vector<glm::dvec3> first(points.begin(), points.begin() + 1500);
  PointHash at_once(first, grid, PointHash::Fill::All);
  PointHash inserted(points, grid, PointHash::Fill::None);
  for (int i = 0; i < int(points.size()); ++i) inserted.insert(i);

  for (int q = 0; q < 300; ++q) {
    const glm::dvec3 p = far + glm::dvec3(u(rng), u(rng), 0.1 * u(rng));
    std::set<int> found_all, found_first;
    inserted.for_each_near(p, [&](int j) { EXPECT_TRUE(found_all.insert(j).second) << "visited twice"; });
    at_once.for_each_near(p, [&](int j) { found_first.insert(j); });
    for (int j = 0; j < int(points.size()); ++j) {
      if (glm::length(points[j] - p) > grid.cell) continue;
      EXPECT_TRUE(found_all.count(j)) << "point " << j << " within a cell was missed";
      if (j < 1500) {
        EXPECT_TRUE(found_first.count(j)) << "point " << j << " within a cell was missed";
      }
    }
    for (int j : found_first) EXPECT_LT(j, 1500);
  }
}

TEST(PointHash, AnEmptyHashVisitsNothing) {
  const std::vector<glm::dvec3> none;
  const PointHash hash(none, CellGrid(glm::dvec3(0), glm::dvec3(1), 0.1), PointHash::Fill::None);
  int visited = 0;
  hash.for_each_near(glm::dvec3(0.5), [&](int) { ++visited; });
  EXPECT_EQ(visited, 0);
}

}  // namespace
}  // namespace paver
