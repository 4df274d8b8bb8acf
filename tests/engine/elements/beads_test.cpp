// Beads (elements/beads.cpp): one in the gap of every three stones in contact, as large as fits
// between their footprints, none on grid or hex, none across the rim.
#include "elements/beads.h"

#include "pipeline/pavement.h"
#include "surface_maps.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace paver {
namespace {

Pavement pendant_stones(Tessellation tessellation, bool beads, double scale = 1) {
  Design design;
  design.pattern.tessellation = tessellation;
  design.elements.gap = 0.1;
  set_stone_size(design, 1.5);
  design.elements.beads.enabled = beads;
  design.elements.beads.scale = scale;
  PavementOptions options;
  options.threads = 1;
  return make_pavement(*test::bundled_map("pendant"), design, options);
}

TEST(Beads, OneInTheGapOfEveryThreeStonesInContactAsLargeAsFits) {
  const Pavement p = pendant_stones(Tessellation::Triangle, true);
  const Elements& stones = p.elements;
  const Elements& beads = p.beads;
  ASSERT_GT(stones.size(), 100u);
  // A triangle lattice has two triangles per stone, less those along the rim.
  EXPECT_GT(beads.size(), 1.6 * double(stones.size()));
  EXPECT_LT(beads.size(), 2.0 * double(stones.size()));
  // Checked against every stone: each bead touches its nearest stones' footprints (scale 1) and
  // overlaps none; it sits on the surface between three of them.
  for (std::size_t b = 0; b < beads.size(); ++b) {
    EXPECT_EQ(beads.kind[b], ElementKind::Bead);
    EXPECT_EQ(beads.shape[b], ShapeKind::Sphere);
    std::vector<double> clearance;
    for (std::size_t s = 0; s < stones.size(); ++s)
      clearance.push_back(glm::length(beads.position[b] - stones.position[s]) - 0.5 * stones.diameter[s] -
                          0.5 * beads.diameter[b]);
    std::sort(clearance.begin(), clearance.end());
    EXPECT_NEAR(clearance[0], 0.0, 1e-9) << "bead " << b << " does not touch its nearest stone";
    EXPECT_LT(clearance[2], 0.15 * 1.5) << "bead " << b << " is not between three stones";
  }
  // In a regular patch, the gap of three stones D apart fits a bead of 2 (D / sqrt 3 - r).
  const double regular = 2 * (1.6 / std::sqrt(3.0) - 0.75);
  std::vector<double> diameters = beads.diameter;
  std::sort(diameters.begin(), diameters.end());
  EXPECT_NEAR(diameters[diameters.size() / 2], regular, 0.05 * regular);
}

TEST(Beads, ScaleGrowsThemAndGridHasNone) {
  const Pavement fitted = pendant_stones(Tessellation::Triangle, true, 1);
  const Pavement grown = pendant_stones(Tessellation::Triangle, true, 1.5);
  ASSERT_EQ(fitted.beads.size(), grown.beads.size());
  for (std::size_t b = 0; b < fitted.beads.size(); ++b)
    EXPECT_NEAR(grown.beads.diameter[b], 1.5 * fitted.beads.diameter[b], 1e-12);
  EXPECT_EQ(pendant_stones(Tessellation::Grid, true).beads.size(), 0u) << "no three stones touch on a grid";
  EXPECT_EQ(pendant_stones(Tessellation::Triangle, false).beads.size(), 0u) << "only when asked";
}

// Beads a caster cannot fill are said to be, in millimetres whatever the surface's unit.
TEST(Beads, FinerThanCastingHoldsAreSaidToBe) {
  const Pavement p = pendant_stones(Tessellation::Triangle, true);
  ASSERT_GT(p.beads.size(), 100u);
  double smallest = 1e300;
  for (const double d : p.beads.diameter) smallest = std::min(smallest, d);
  ASSERT_GT(smallest, kFinestCastBeadMm) << "the case: 1.5 mm stones, 0.1 mm gap, beads that cast";
  EXPECT_FALSE(fine_beads_warning(p.beads, Units::Millimetre).has_value());
  // Read in centimetres, the same beads are ten times larger.
  EXPECT_FALSE(fine_beads_warning(p.beads, Units::Centimetre).has_value());
  Elements fine = p.beads;
  fine.diameter.front() = 0.15;
  fine.diameter.back() = 0.0311;
  const std::optional<std::string> w = fine_beads_warning(fine, Units::Millimetre);
  ASSERT_TRUE(w.has_value());
  EXPECT_NE(w->find("2 of " + std::to_string(fine.size()) + " beads are under 0.2 mm (the smallest 0.031 mm)"),
            std::string::npos)
      << *w;
  EXPECT_NE(w->find("raise elements.beads.scale or the gap"), std::string::npos) << *w;
}

}  // namespace
}  // namespace paver
