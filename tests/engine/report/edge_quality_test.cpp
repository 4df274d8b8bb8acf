// Tests for engine/report/edge_quality.cpp: the bare spots and the rim metal the report gives,
// checked against a sampling of the surface and the rims written in the test (spot_probe.h), on a
// flat square paved with a triangle lattice by hand, one stone taken out of its middle.
#include "report/edge_quality.h"

#include "all_pairs.h"
#include "pipeline/pavement.h"
#include "report/verdict.h"
#include "spot_probe.h"
#include "surface_maps.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace paver {
namespace {

constexpr double kStone = 0.1, kGap = 0.01, kMargin = 0.02;

Elements square_pave(glm::dvec3& hole) { return test::square_lattice(kStone, kGap, kMargin, hole); }

EdgeBasis square_basis() {
  EdgeBasis basis;
  basis.spots.stone = kStone;
  basis.spots.spot_stone = kSpotStoneShare * kStone;
  basis.spots.gap = kGap;
  basis.spots.margin = kMargin;
  basis.rims = {0};
  return basis;
}

TEST(EdgeQuality, TheSpotsAreWhereAnIndependentSamplingFindsRoom) {
  const SurfaceMap& map = test::flat_unit_square();
  glm::dvec3 hole;
  const Elements e = square_pave(hole);
  const EdgeQuality q = measure_edges(map, e, square_basis());
  ASSERT_TRUE(q.measured);
  const double spot = kSpotStoneShare * kStone;
  const test::SpotProbe probe = test::probe_spots(map.mesh, e, kGap, kMargin, spot, kStone / 40, 4 * kStone);
  // The widest stone: the engine samples the surface more coarsely (d / 8), never beyond the truth.
  EXPECT_LE(q.largest_fit, probe.widest + 1e-9);
  EXPECT_GE(q.largest_fit, probe.widest - kStone / 8);
  EXPECT_GE(probe.widest, kStone * (1 - 1e-6)) << "the stone taken out leaves room for one";
  // The hole is one of the spots.
  ASSERT_GT(q.bare_spots, 0);
  EXPECT_TRUE(std::any_of(q.spots.begin(), q.spots.end(),
                          [&](const BareSpot& s) { return glm::length(s.position - hole) < 0.5 * kStone; }));
  // Every spot the engine says fits the stone it says, by the test's own measure of room there.
  for (const BareSpot& s : q.spots) {
    double room = 0.5 * 4 * kStone;
    for (std::size_t k = 0; k < e.size(); ++k)
      room = std::min(room, glm::length(s.position - e.position[k]) - 0.5 * kStone - kGap);
    room = std::min(room, std::min({s.position.x, s.position.y, 1 - s.position.x, 1 - s.position.y}) - kMargin);
    EXPECT_NEAR(s.fits, 2 * room, 1e-9);
    EXPECT_GE(s.fits, spot);
  }
  // None missed: every sample with clearly room for a spot stone lies by one the engine found.
  for (const glm::dvec3& p : test::probe_spots(map.mesh, e, kGap, kMargin, spot + kStone / 8, kStone / 40, 4 * kStone)
                                 .fitting)
    EXPECT_TRUE(std::any_of(q.spots.begin(), q.spots.end(), [&](const BareSpot& s) {
      return glm::length(s.position - p) <= spot + kGap + kStone / 8;
    })) << "a spot at (" << p.x << ", " << p.y << ") was missed";
  EXPECT_EQ(q.bare_spots, long(q.spots.size()));
}

TEST(EdgeQuality, TheRimMetalIsTheGirdlesDistanceFromTheRimAsSampledApart) {
  const SurfaceMap& map = test::flat_unit_square();
  glm::dvec3 hole;
  const Elements e = square_pave(hole);
  const EdgeQuality q = measure_edges(map, e, square_basis());
  std::vector<double> metal = test::probe_rim_metal(map.mesh, e, {0}, kMargin, kStone / 100);
  std::sort(metal.begin(), metal.end());
  const double p95 = metal[std::size_t(0.95 * double(metal.size()))] / kStone, most = metal.back() / kStone;
  EXPECT_GT(q.rim_samples, 4 * kRimSamplesPerStone / kStone * 0.9);
  EXPECT_NEAR(q.rim_metal_p95, p95, 0.02);
  EXPECT_NEAR(q.rim_metal_max, most, 0.02);
  EXPECT_GT(q.rim_metal_p95, 0.3) << "a lattice clipped at the square's edge leaves teeth";
}

TEST(EdgeQuality, NoStoneDesignNoFigures) {
  EdgeBasis none;
  EXPECT_FALSE(measure_edges(test::flat_unit_square(), Elements{}, none).measured);
}

// Issue 40's runs, by default (tri pave: rows along every rim, the spots closed): a ring band at
// 1.3 mm and a pierced pendant at 1.5 mm with a 0.3 mm margin, gap 0.1. No place inside the margin
// fits another stone of 0.8 d and the rims are even, by the engine's figures and by this test's
// own sampling (d / 40 over the surface, d / 100 along the rims, every element); every stone is
// the size asked; the verdict is ok.
TEST(EdgeQuality, TriPaveByDefaultLeavesNoSpotAndEvenRims) {
  struct Run {
    std::string surface;
    double stone, margin;
  };
  // The ring, the pierced pendant, the domed pendant whose vacancies the closing once left (5 at
  // 1.3 mm), and the ring as a scanner writes it (ring_scan: uneven triangles, wavy rims).
  for (const Run& run : {Run{"ring_band", 1.3, 0}, Run{"pendant_pierced", 1.5, 0.3}, Run{"pendant", 1.3, 0},
                         Run{"ring_scan", 1.5, 0}}) {
    const auto map = test::bundled_map(run.surface);
    Design design;
    design.pattern.tessellation = Tessellation::Triangle;
    design.elements.gap = 0.1;
    design.elements.margin = run.margin;
    set_stone_size(design, run.stone);
    const Pavement p = make_pavement(*map, design);
    const Elements& e = p.elements;
    EXPECT_EQ(p.design.elements.rim_rows, RimRows::All) << run.surface;
    ASSERT_TRUE(p.after.edges.measured && p.after.edges.pave) << run.surface;
    EXPECT_EQ(p.after.edges.bare_spots, 0) << run.surface;
    EXPECT_LE(p.after.edges.rim_metal_p95, kUnevenRim) << run.surface;
    const Verdict verdict = judge_pavement(p.after);
    EXPECT_TRUE(verdict.ok) << run.surface << ": " << (verdict.problems.empty() ? "" : verdict.problems.front());
    for (const double d : e.diameter) ASSERT_NEAR(d, run.stone, 1e-3 * run.stone) << run.surface;
    EXPECT_EQ(test::all_pairs(e, 0.1).violations, 0) << run.surface;
    // Stones as ordered: the median gap between nearest neighbours (every pair, here) within 3% of D
    // of the gap asked.
    std::vector<double> nearest(e.size(), std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < e.size(); ++i)
      for (std::size_t j = 0; j < e.size(); ++j)
        if (i != j) nearest[i] = std::min(nearest[i], glm::length(e.position[i] - e.position[j]) - run.stone);
    std::nth_element(nearest.begin(), nearest.begin() + std::ptrdiff_t(nearest.size() / 2), nearest.end());
    const double median_gap = nearest[nearest.size() / 2];
    EXPECT_LE(std::abs(median_gap - 0.1), 0.03 * (run.stone + 0.1)) << run.surface << ": median gap " << median_gap;
    const double spot = kSpotStoneShare * run.stone;
    const test::SpotProbe probe = test::probe_spots(map->mesh, e, 0.1, run.margin, spot, run.stone / 40, 4 * run.stone);
    EXPECT_TRUE(probe.fitting.empty()) << run.surface << ": " << probe.fitting.size() << " samples fit " << spot
                                       << " (the widest " << probe.widest << ")";
    std::vector<int> rims(map->mesh.boundary_loops.size());
    for (std::size_t l = 0; l < rims.size(); ++l) rims[l] = int(l);
    std::vector<double> metal = test::probe_rim_metal(map->mesh, e, rims, run.margin, run.stone / 100);
    ASSERT_FALSE(metal.empty());
    std::sort(metal.begin(), metal.end());
    EXPECT_LE(metal[std::size_t(0.95 * double(metal.size()))] / run.stone, kUnevenRim) << run.surface;
  }
}

}  // namespace
}  // namespace paver
