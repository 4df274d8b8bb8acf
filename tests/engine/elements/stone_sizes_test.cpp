// Tests for engine/elements/stone_sizes.cpp (issue 43): the pierced pendant paved with 1.5 mm
// stones, 0.1 apart, 0.3 from the rims, then filled with the stocked sizes 1.3, 1.1 and 0.9 mm:
// checked by a sampling of the surface written in the test (spot_probe.h) and a loop over all
// pairs, not by the engine's own search.
#include "elements/stone_sizes.h"

#include "all_pairs.h"
#include "map/boundary_index.h"
#include "pipeline/pave_once.h"
#include "spot_probe.h"
#include "plain_edges.h"
#include "surface_maps.h"

#include <gtest/gtest.h>

#include <map>

namespace paver {
namespace {

constexpr double kStone = 1.5, kGap = 0.1, kMargin = 0.3;

Design pendant_design(std::vector<double> fill_sizes) {
  Design design;
  design.pattern.tessellation = Tessellation::Triangle;
  design.elements.gap = kGap;
  design.elements.margin = kMargin;
  design.elements.fill_sizes = std::move(fill_sizes);
  set_stone_size(design, kStone);
  // The room the main size leaves as the lattice lays it: the spots' closing would take it first.
  return test::with_plain_edges(design);
}

TEST(StoneSizes, WhatTheMainSizeLeavesGetsTheLargestStockedSizeThatFits) {
  const SurfaceMap& map = *test::bundled_map("pendant_pierced");
  PaveState state = pave_until(map, pendant_design({0.9, 1.3, 1.1}), {}, "fill_sizes");
  const Elements& e = state.pavement.elements;
  const std::size_t before = e.size();
  const test::SpotProbe bare = test::probe_spots(map.mesh, e, kGap, kMargin, 0.9, 0.9 / 20, 4 * kStone);
  ASSERT_FALSE(bare.fitting.empty()) << "the case: the main size leaves places where a 0.9 mm stone fits";

  pave_step("fill_sizes", map, {}, state);
  const SizeFill& fill = state.pavement.size_fill;
  ASSERT_EQ(fill.sizes.size(), 3u);
  EXPECT_EQ(fill.sizes[0].diameter, 1.3) << "largest first, whatever the order given";
  EXPECT_EQ(std::size_t(fill.added()), e.size() - before);

  std::map<double, int> used;
  for (const double d : e.diameter) ++used[d];
  for (const auto& [d, n] : used) EXPECT_TRUE(d == 1.5 || d == 1.3 || d == 1.1 || d == 0.9) << d << " mm is not stocked";
  EXPECT_GE(used.size(), 2u);
  // A larger size goes wherever it fits before a smaller is tried: no 0.9 stone's place fits 1.1.
  const test::SpotProbe after = test::probe_spots(map.mesh, e, kGap, kMargin, 0.9 * (1 + 1e-6), 0.9 / 20, 4 * kStone);
  EXPECT_TRUE(after.fitting.empty()) << after.fitting.size() << " samples still fit a 0.9 mm stone (the widest "
                                     << after.widest << ")";
  EXPECT_EQ(test::all_pairs(e, kGap).violations, 0);
  const BoundaryIndex rims(map.mesh, 2 * kStone);
  for (std::size_t i = before; i < e.size(); ++i) {
    EXPECT_GE(rims.nearest(e.position[i]).distance, 0.5 * e.diameter[i] + kMargin - 1e-9) << "stone " << i;
    EXPECT_EQ(e.kind[i], ElementKind::Vertex);
    EXPECT_NEAR(glm::length(e.normal[i]), 1.0, 1e-12);
  }
}

TEST(StoneSizes, EachSmallerSizeFillsOnlyWhereTheLargerLeftRoom) {
  // The 1.1 mm stones alone, then 1.3 and 1.1: with 1.3 first, fewer 1.1 are needed.
  const SurfaceMap& map = *test::bundled_map("pendant_pierced");
  PaveState alone = pave_until(map, pendant_design({1.1}), {}, "ids");
  PaveState both = pave_until(map, pendant_design({1.3, 1.1}), {}, "ids");
  ASSERT_EQ(alone.pavement.size_fill.sizes.size(), 1u);
  ASSERT_EQ(both.pavement.size_fill.sizes.size(), 2u);
  EXPECT_GT(both.pavement.size_fill.sizes[0].added, 0);
  EXPECT_LT(both.pavement.size_fill.sizes[1].added, alone.pavement.size_fill.sizes[0].added);
}

}  // namespace
}  // namespace paver
