// Tests for engine/elements/bare_spots.cpp: on the pierced pendant paved with 1.5 mm stones, 0.1
// apart, 0.3 from the rims and a row along every rim, the pass leaves spots where a stone of 0.8 d
// fits (by a sampling of the surface written in the test, spot_probe.h); the closing step, run on
// that state, leaves none, breaks no contact (all pairs) and keeps every stone inside the margin.
#include "elements/bare_spots.h"

#include "all_pairs.h"
#include "map/boundary_index.h"
#include "pipeline/pave_once.h"
#include "spot_probe.h"
#include "surface_maps.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace paver {
namespace {

Design pave_design(double stone) {
  Design design;
  design.pattern.topology = Topology::Lattice;
  design.elements.gap = 0.1;
  design.elements.margin = 0.3;
  design.elements.rim_rows = RimRows::All;
  design.elements.close_spots = true;
  set_stone_size(design, stone);
  design.pattern.tessellation = Tessellation::Triangle;
  return design;
}

// Paves `design` up to the closing, checks by the test's own sampling that spots are left, closes
// them and checks that none is: no sample fits 0.8 d, no pair breaks the rule, every stone is d and
// inside the margin. Returns what the closing did.
SpotClosing expect_closing_leaves_no_spot(const SurfaceMap& map, const Design& design, double d) {
  const double spot = 0.8 * d, gap = design.elements.gap, margin = design.elements.margin;
  PaveState state = pave_until(map, design, {}, "close_spots");
  const Elements& e = state.pavement.elements;
  const test::SpotProbe before = test::probe_spots(map.mesh, e, gap, margin, spot, d / 20, 4 * d);
  EXPECT_FALSE(before.fitting.empty()) << "the case: the pass leaves spots";

  pave_step("close_spots", map, {}, state);
  const test::SpotProbe after = test::probe_spots(map.mesh, e, gap, margin, spot, d / 20, 4 * d);
  EXPECT_TRUE(after.fitting.empty()) << after.fitting.size() << " samples still fit a stone of 0.8 d (the widest "
                                     << after.widest << ")";
  EXPECT_EQ(test::all_pairs(e, gap).violations, 0);
  const BoundaryIndex rims(map.mesh, 2 * d);
  for (std::size_t i = 0; i < e.size(); ++i) {
    EXPECT_DOUBLE_EQ(e.diameter[i], d) << "every stone as ordered";
    EXPECT_GE(rims.nearest(e.position[i]).distance, 0.5 * d + margin) << "stone " << i << " inside the margin";
  }
  return state.pavement.spots_closed;
}

TEST(BareSpots, TheClosingStepLeavesNoSpotWhereAStoneOfEightTenthsFits) {
  const SpotClosing closed = expect_closing_leaves_no_spot(*test::bundled_map("pendant_pierced"), pave_design(1.5), 1.5);
  EXPECT_GT(closed.added, 0);
  EXPECT_GT(closed.pushed, 0) << "some spots were narrower than a stone: their neighbours made room";
}

// Pavé with melee on its edges (the bundled pierced pendant design: 1.44 mm V-stones, 0.84 mm
// E-stones): the pushing moves V-stones only and closed none of its spots; the closing then puts the
// E-elements' size where a V-stone cannot go. No sample of the surface keeps room for 0.8 d, no pair
// breaks the contact rule, and every stone is one of the design's two sizes.
TEST(BareSpots, AMixedDesignsSpotsTakeItsEdgeStonesSize) {
  const SurfaceMap& map = *test::bundled_map("pendant_pierced");
  Design design;
  design.pattern.tessellation = Tessellation::Triangle;
  design.pattern.spacing = 2.4;
  design.elements.vertex.shape = ShapeKind::Gem;
  design.elements.vertex.scale = 0.6;
  EdgeElementDesign edge;
  edge.t = 0.5, edge.scale = 0.35, edge.shape = ShapeKind::Gem;
  design.elements.edge = {edge};
  design.elements.close_spots = true;
  const double d = 0.6 * 2.4, melee = 0.35 * 2.4, spot = 0.8 * d;
  PaveState state = pave_until(map, design, {}, "close_spots");
  const Elements& e = state.pavement.elements;
  const test::SpotProbe before = test::probe_spots(map.mesh, e, 0, 0, spot, d / 20, 4 * d);
  ASSERT_FALSE(before.fitting.empty()) << "the case: the mixed lattice leaves spots";

  pave_step("close_spots", map, {}, state);
  const SpotClosing& closed = state.pavement.spots_closed;
  EXPECT_GT(closed.of_edge_size, 0);
  EXPECT_GE(closed.added, closed.of_edge_size);
  const test::SpotProbe after = test::probe_spots(map.mesh, e, 0, 0, spot, d / 20, 4 * d);
  EXPECT_TRUE(after.fitting.empty()) << after.fitting.size() << " samples still fit a stone of 0.8 d (the widest "
                                     << after.widest << ")";
  EXPECT_EQ(test::all_pairs(e, 0).violations, 0);
  for (std::size_t i = 0; i < e.size(); ++i)
    ASSERT_TRUE(std::abs(e.diameter[i] - d) < 1e-12 || std::abs(e.diameter[i] - melee) < 1e-12)
        << "stone " << i << " of " << e.diameter[i] << ": not one of the design's sizes";
}

TEST(BareSpots, WhereAWholeStoneFitsOneIsPutAndNothingNearItMoves) {
  const SurfaceMap& map = test::flat_unit_square();
  glm::dvec3 hole;
  // The lattice 0.02 apart, the closing's gap 0.01: the stone taken out leaves room for one more.
  Elements e = test::square_lattice(0.1, 0.02, 0.05, hole);
  ElementsDesign spec;
  spec.vertex.shape = ShapeKind::Gem;
  SpotBasis basis;
  basis.stone = 0.1, basis.spot_stone = 0.08, basis.gap = 0.01, basis.margin = 0.05;
  const Elements before = e;
  close_bare_spots(map, e, spec, 0.12, basis);
  EXPECT_TRUE(std::any_of(e.position.begin() + std::ptrdiff_t(before.size()), e.position.end(),
                          [&](const glm::dvec3& p) { return glm::length(p - hole) < 0.01; }))
      << "a stone in the hole";
  for (std::size_t i = 0; i < before.size(); ++i)
    if (glm::length(before.position[i] - hole) < 0.3) {
      EXPECT_EQ(e.position[i], before.position[i]) << i;
    }
  EXPECT_EQ(test::all_pairs(e, 0.01).violations, 0);
  for (const BareSpot& s : find_bare_spots(map, e, basis).spots)
    EXPECT_GT(glm::length(s.position - hole), 0.3) << "a spot left by the hole";
}

// The spots the closing used to leave on the domed pendant (5 at 1.3 mm) were vacancies: a lattice
// site empty, its six neighbours nearer its centre than on a plane (the dome's positive curvature)
// and the lattice around at contact. No spreading closes one (the six touch each other before the
// hole shrinks); a stone goes in once the zone making room for it is wide enough to hold the slack.
TEST(BareSpots, TheDomesVacanciesTakeAStoneEach) {
  Design design = pave_design(1.3);
  design.elements.margin = 0;
  EXPECT_GT(expect_closing_leaves_no_spot(*test::bundled_map("pendant"), design, 1.3).pushed, 0);
}

}  // namespace
}  // namespace paver
