// Beads (elements/beads.cpp): every stone held all round by at least three beads at its girdle,
// rim stones included, each bead castable, off every table, clear of the other beads and on the
// metal; checked here over all pairs and every rim segment, apart from the engine's grids.
#include "elements/beads.h"

#include "pipeline/pavement.h"
#include "plain_edges.h"
#include "surface_maps.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace paver {
namespace {

Pavement paved(const std::string& surface, Tessellation tessellation, bool beads, double min_diameter = 0.5,
               double over = 0.05, double scale = 1, double margin = 0) {
  Design design;
  design.pattern.tessellation = tessellation;
  design.elements.gap = 0.1;
  design.elements.margin = margin;
  set_stone_size(design, 1.5);
  design.elements.beads = {beads, scale, min_diameter, over};
  test::with_plain_edges(design);  // the beads of the lattice as laid: their sizes are its own
  PavementOptions options;
  options.threads = 1;
  return make_pavement(*test::bundled_map(surface), design, options);
}

double to_rims(const SurfaceMesh& mesh, const glm::dvec3& p) {
  double nearest = 1e300;
  for (const std::vector<int>& loop : mesh.boundary_loops)
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const glm::dvec3 a = mesh.positions[loop[k]], b = mesh.positions[loop[(k + 1) % loop.size()]];
      const double t = std::clamp(glm::dot(p - a, b - a) / glm::dot(b - a, b - a), 0.0, 1.0);
      nearest = std::min(nearest, glm::length(p - (a + t * (b - a))));
    }
  return nearest;
}

// The hold counted the plainest way: every bead against every stone.
void expect_every_stone_held(const std::string& surface, const Pavement& p) {
  const Elements& stones = p.elements;
  const Elements& beads = p.beads;
  ASSERT_GT(stones.size(), 100u) << surface;
  const SurfaceMesh& mesh = test::bundled_map(surface)->mesh;
  for (std::size_t b = 0; b < beads.size(); ++b) {
    ASSERT_GE(beads.diameter[b], 0.5) << surface << ": bead " << b << " under the castable least";
    EXPECT_GE(to_rims(mesh, beads.position[b]), 0.5 * beads.diameter[b] - 1e-9) << surface << ": bead " << b << " off the metal";
    for (std::size_t o = b + 1; o < beads.size(); ++o)
      ASSERT_GE(glm::length(beads.position[b] - beads.position[o]), 0.5 * (beads.diameter[b] + beads.diameter[o]) + 0.1)
          << surface << ": beads " << b << " and " << o << " run together";
  }
  int open_wider = 0;
  for (std::size_t s = 0; s < stones.size(); ++s) {
    const double d = stones.diameter[s];
    std::vector<double> angles;
    const glm::dvec3 n = stones.normal[s];
    const glm::dvec3 t = glm::normalize(glm::cross(n, std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
    for (std::size_t b = 0; b < beads.size(); ++b) {
      const glm::dvec3 r = beads.position[b] - stones.position[s];
      const double into = 0.5 * (d + beads.diameter[b]) - glm::length(r);
      ASSERT_LE(into, 0.22 * d + 1e-9) << surface << ": bead " << b << " reaches past stone " << s << "'s table";
      if (into >= -0.05 * d) angles.push_back(std::atan2(glm::dot(r, glm::cross(n, t)), glm::dot(r, t)));
    }
    EXPECT_GE(angles.size(), 3u) << surface << ": stone " << s << " (id " << stones.id[s] << ")";
    std::sort(angles.begin(), angles.end());
    double open = angles.empty() ? 2 * std::numbers::pi : angles.front() + 2 * std::numbers::pi - angles.back();
    for (std::size_t k = 1; k < angles.size(); ++k) open = std::max(open, angles[k] - angles[k - 1]);
    if (open > std::numbers::pi + 1e-6) ++open_wider;
  }
  const BeadHold hold = measure_bead_hold(stones, beads);
  EXPECT_EQ(open_wider, int(hold.underheld.size())) << surface << ": the report's count is the test's";
  EXPECT_LE(open_wider, 1) << surface << ": stones open on one side";
}

TEST(Beads, EveryStoneIsHeldByThreeCastableBeadsRimStonesIncluded) {
  for (const std::string surface : {"ring_band", "pendant_pierced"}) expect_every_stone_held(surface, paved(surface, Tessellation::Triangle, true));
  const Pavement margin = paved("pendant_pierced", Tessellation::Triangle, true, 0.5, 0.05, 1, 0.3);
  expect_every_stone_held("pendant_pierced", margin);
  EXPECT_TRUE(measure_bead_hold(margin.elements, margin.beads).underheld.empty())
      << "with a margin, rim stones have metal for their beads";
}

TEST(Beads, AGridsStonesAreHeldToo) {
  const Pavement grid = paved("pendant", Tessellation::Grid, true);
  EXPECT_GT(grid.beads.size(), grid.elements.size()) << "beads of their own, no three stones being in contact";
  expect_every_stone_held("pendant", grid);
  EXPECT_EQ(paved("pendant", Tessellation::Triangle, false).beads.size(), 0u) << "only when asked";
}

// With no least size and no reach over the girdles, a bead between three stones is as large as
// fits (scale 1) or scaled: in a regular patch 2 (D / sqrt 3 - r).
TEST(Beads, BetweenThreeStonesABeadIsAsLargeAsFitsTimesItsScale) {
  const Pavement fitted = paved("pendant", Tessellation::Triangle, true, 1e-6, 0, 1);
  const Pavement grown = paved("pendant", Tessellation::Triangle, true, 1e-6, 0, 1.2);
  std::vector<double> diameters = fitted.beads.diameter;
  std::sort(diameters.begin(), diameters.end());
  const double regular = 2 * (1.6 / std::sqrt(3.0) - 0.75);
  EXPECT_NEAR(diameters[diameters.size() / 2], regular, 0.05 * regular);
  std::vector<double> larger = grown.beads.diameter;
  std::sort(larger.begin(), larger.end());
  EXPECT_NEAR(larger[larger.size() / 2], 1.2 * regular, 0.06 * regular);
  // Each touches its nearest stone: as large as fits.
  for (std::size_t b = 0; b < std::min<std::size_t>(fitted.beads.size(), 50); ++b) {
    double nearest = 1e300;
    for (std::size_t s = 0; s < fitted.elements.size(); ++s)
      nearest = std::min(nearest, glm::length(fitted.beads.position[b] - fitted.elements.position[s]) -
                                      0.5 * (fitted.elements.diameter[s] + fitted.beads.diameter[b]));
    EXPECT_LT(nearest, 1e-9) << "bead " << b;
  }
}

// Beads a caster cannot fill are said to be, in millimetres whatever the surface's unit.
TEST(Beads, FinerThanCastingHoldsAreSaidToBe) {
  const Pavement p = paved("pendant", Tessellation::Triangle, true);
  ASSERT_GT(p.beads.size(), 100u);
  EXPECT_FALSE(fine_beads_warning(p.beads, Units::Millimetre).has_value());
  EXPECT_FALSE(fine_beads_warning(p.beads, Units::Centimetre).has_value());
  Elements fine = p.beads;
  fine.diameter.front() = 0.15;
  fine.diameter.back() = 0.0311;
  const std::optional<std::string> w = fine_beads_warning(fine, Units::Millimetre);
  ASSERT_TRUE(w.has_value());
  EXPECT_NE(w->find("2 of " + std::to_string(fine.size()) + " beads are under 0.2 mm (the smallest 0.031 mm)"),
            std::string::npos)
      << *w;
  EXPECT_NE(w->find("raise elements.beads.min_diameter"), std::string::npos) << *w;
}

}  // namespace
}  // namespace paver
