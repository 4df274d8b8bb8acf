#include "pattern/bar_length_floor.h"

#include "core/contact_rule.h"

#include <gtest/gtest.h>

#include <cmath>

namespace paver {
namespace {

Design gems(Tessellation t, double gap) {
  Design d;
  d.pattern.tessellation = t;
  d.pattern.spacing = 1;
  d.elements.vertex = {true, 0.6, ShapeKind::Gem};
  d.elements.edge = {EdgeElementDesign{0.5, 0.35, ShapeKind::Gem, {}}};
  d.elements.gap = gap;
  return d;
}

TEST(BarLengthFloor, TouchingVertexElementsNeedABarOfTheirDiameter) {
  Design d;
  d.pattern.spacing = 2;
  EXPECT_DOUBLE_EQ(bar_length_floor(d), 2);
  d.elements.gap = 0.1;
  EXPECT_DOUBLE_EQ(bar_length_floor(d), 2.1);
  EXPECT_DOUBLE_EQ(particle_contact_distance(d), 2.1 * (1 + 2 * kContactAim));
}

TEST(BarLengthFloor, AMidpointGemNeedsTwiceItsContactWithTheVertexGem) {
  // Vertex 0.6, edge 0.35 at the middle: (0.6 + 0.35) / 2 from each end, so the bar is 0.95
  // (beside ones at 60 degrees, the edge gems are 0.5 apart and need only 0.35).
  EXPECT_NEAR(bar_length_floor(gems(Tessellation::Triangle, 0)), 0.95, 1e-12);
  EXPECT_NEAR(bar_length_floor(gems(Tessellation::Triangle, 0.05)), 1.05, 1e-12);
  EXPECT_NEAR(bar_length_floor(gems(Tessellation::Hexagon, 0)), 0.95, 1e-12);
}

TEST(BarLengthFloor, EdgeGemsBesideEachOtherSetItWhenTheyAreLarge) {
  // Edge gems at t = 0.25 and 0.75, 0.45 wide, no vertex element: on one bar they are 0.5 apart
  // (0.45 / 0.5 = 0.9); on bars 60 degrees apart the inner ones are 0.25 apart (1.8), at 120
  // degrees 0.25 sqrt 3 (1.039).
  Design d;
  d.pattern.spacing = 1;
  d.elements.vertex.enabled = false;
  d.elements.edge = {EdgeElementDesign{0.25, 0.45, ShapeKind::Sphere, {}},
                     EdgeElementDesign{0.75, 0.45, ShapeKind::Sphere, {}}};
  d.pattern.tessellation = Tessellation::Triangle;
  EXPECT_NEAR(bar_length_floor(d), 1.8, 1e-12);
  d.pattern.tessellation = Tessellation::Hexagon;
  EXPECT_NEAR(bar_length_floor(d), 0.45 / (0.25 * std::sqrt(3.0)), 1e-12);
}

}  // namespace
}  // namespace paver
