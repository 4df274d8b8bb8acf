// A band's seamless map (issue 12, "Bands: seamless"): a periodic map whose period is the band's
// length, with no fold, and a lattice that closes around it with no seam: on a right circular
// cylinder every element away from the rims has its nearest neighbour at 1.00 +- 0.01 lattice
// distances, across the seam too (checked over all pairs, in 3D, not through the map).
#include "map/seamless_band.h"
#include "map/surface_map.h"
#include "mesh/triangle_geometry.h"
#include "pattern/band_closure.h"
#include "pipeline/pavement.h"
#include "surface_maps.h"
#include "test_meshes.h"
#include "map/map_quality.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>
#include <limits>
#include <numbers>

namespace paver {
namespace {

constexpr double kRadius = 10, kHeight = 8;

const SurfaceMap& cylinder_map() {
  static const SurfaceMap map = build_surface_map(test::band_surface(120, 16, [](double u, double v) {
    const double a = 2 * std::numbers::pi * u;
    return glm::dvec3(kRadius * std::cos(a), kRadius * std::sin(a), kHeight * v);
  }));
  return map;
}

TEST(SeamlessBand, CylinderUnrollsToAStripWithoutFolds) {
  const SurfaceMap& annulus = cylinder_map();
  ASSERT_TRUE(annulus.seamless) << annulus.seamless_unavailable;
  const SurfaceMap& band = *annulus.seamless;
  EXPECT_FALSE(map_wraps(annulus));
  ASSERT_TRUE(map_wraps(band));
  // The period is the cylinder's circumference, less what the polygon cuts off.
  const double polygon = 120 * 2 * kRadius * std::sin(std::numbers::pi / 120);
  EXPECT_NEAR(band.period, polygon, 1e-3 * polygon);
  EXPECT_NEAR(band.parameterization.quality.stretch_mean, 1.0, 1e-3);
  // Every triangle in one piece and positive; together they cover exactly one period.
  double area = 0;
  for (int f = 0; f < band.mesh.face_count(); ++f) {
    const auto c = triangle_uv(band, f);
    const double a = detail::signed_area(c[0], c[1], c[2]);
    EXPECT_GT(a, 0) << "triangle " << f;
    area += a;
  }
  EXPECT_NEAR(area, band.period * kHeight, 1e-3 * area);
}

// Bands whose ARAP would let the rims slide over each other: the line search refuses such steps,
// so every band here, the scanned one too, gets a seamless map with its triangles positive, one
// period's area, and rims that go once around and never cross (over three periods, all pairs of
// rim segments).
TEST(SeamlessBand, EveryBundledAndScannedBandGetsOneWithItsRimsApart) {
  for (const std::string name : {"bangle", "ring_band", "vase_band", "bunnyhead_band"}) {
    const auto annulus = test::named_map(name);
    ASSERT_TRUE(annulus->seamless) << name << ": " << annulus->seamless_unavailable;
    const SurfaceMap& band = *annulus->seamless;
    double area = 0;
    int negative = 0;
    for (int f = 0; f < band.mesh.face_count(); ++f) {
      const auto c = triangle_uv(band, f);
      const double a = detail::signed_area(c[0], c[1], c[2]);
      negative += a <= 0;
      area += a;
    }
    EXPECT_EQ(negative, 0) << name;
    EXPECT_NEAR(area, surface_area(band.mesh), 1e-6 * area) << name;
    std::vector<glm::dvec2> rim;
    std::vector<glm::ivec2> segments;
    for (const std::vector<int>& loop : band.mesh.boundary_loops) {
      std::vector<glm::dvec2> unrolled;
      for (const int v : loop)
        unrolled.push_back(unrolled.empty() ? band.uv[v] : nearest_image(band, band.uv[v], unrolled.back()));
      const double closing = nearest_image(band, unrolled.front(), unrolled.back()).x - unrolled.front().x;
      EXPECT_NEAR(std::abs(closing), band.period, 1e-6 * band.period) << name << ": a rim goes once around";
      const int first = int(rim.size());
      for (int copy = -1; copy <= 1; ++copy)
        for (const glm::dvec2& q : unrolled) rim.push_back(q + glm::dvec2(copy * closing, 0));
      for (int k = first; k + 1 < int(rim.size()); ++k) segments.emplace_back(k, k + 1);
    }
    EXPECT_EQ(count_segment_intersections(segments, rim), 0) << name;
  }
}

TEST(SeamlessBand, EveryPointOfThePeriodIsFoundOnce) {
  const SurfaceMap& band = *cylinder_map().seamless;
  // Points along the middle of the strip, over three periods: each lifts to the cylinder at the
  // height of its v and the angle of its u.
  const double middle_v = 0.5 * (band.uv_min.y + band.uv_max.y);
  for (int k = -150; k <= 150; ++k) {
    const glm::dvec2 p(band.period_origin + k * band.period / 100.0, middle_v);
    glm::dvec3 bary;
    const int t = locate_on_map(band, p, bary);
    ASSERT_GE(t, 0) << "u " << p.x;
    const glm::ivec3 tri = band.mesh.triangles[t];
    const glm::dvec3 q = bary.x * band.mesh.positions[tri.x] + bary.y * band.mesh.positions[tri.y] +
                         bary.z * band.mesh.positions[tri.z];
    EXPECT_NEAR(q.z, 0.5 * kHeight, 0.05 * kHeight);
    EXPECT_NEAR(glm::length(glm::dvec2(q)), kRadius, 0.01 * kRadius);
  }
}

// The nearest neighbour of each vertex element at least one diameter from both rims, over all
// pairs, in lattice distances.
std::pair<double, double> nearest_neighbour_range(const Pavement& p) {
  double lo = std::numeric_limits<double>::infinity(), hi = 0;
  const Elements& e = p.elements;
  int counted = 0;
  for (size_t i = 0; i < e.size(); ++i) {
    if (e.kind[i] != ElementKind::Vertex) continue;
    const double z = e.position[i].z;
    if (z < e.diameter[i] || z > kHeight - e.diameter[i]) continue;
    double nearest = std::numeric_limits<double>::infinity();
    for (size_t j = 0; j < e.size(); ++j)
      if (j != i && e.kind[j] == ElementKind::Vertex) nearest = std::min(nearest, glm::length(e.position[i] - e.position[j]));
    lo = std::min(lo, nearest / p.design.pattern.spacing);
    hi = std::max(hi, nearest / p.design.pattern.spacing);
    ++counted;
  }
  EXPECT_GT(counted, 100);
  return {lo, hi};
}

class SeamlessCylinder : public ::testing::TestWithParam<Tessellation> {};

TEST_P(SeamlessCylinder, NeighboursAreOneLatticeStepApartAcrossTheSeamToo) {
  Design design;
  design.pattern.tessellation = GetParam();
  design.pattern.spacing = 0.63;
  design.elements.vertex.scale = 0.8;
  for (const BandRows rows : {BandRows::Along, BandRows::Across})
    for (const bool optimize : {false, true}) {
      design.placement.band_rows = rows;
      PavementOptions options;
      options.optimize = optimize;
      const Pavement p = make_pavement(cylinder_map(), design, options);
      ASSERT_TRUE(p.seamless);
      ASSERT_TRUE(p.band_closure);
      const BandClosure& c = *p.band_closure;
      const std::string what = describe_band_closure(c) + (optimize ? ", optimized" : ", as laid");
      // A whole number of steps closes the band, and D moved by at most half a step's worth.
      const UnitCell& cell = p.cell;
      const double step = glm::length(double(c.step.x) * cell.a1 + double(c.step.y) * cell.a2);
      EXPECT_NEAR(c.around * step, cylinder_map().seamless->period, 1e-9 * c.around * step) << what;
      EXPECT_LE(std::abs(c.spacing - 0.63), 0.5 * 0.63 / c.around * step / c.spacing) << what;
      EXPECT_EQ(p.design.pattern.spacing, c.spacing);
      const auto [lo, hi] = nearest_neighbour_range(p);
      // As laid, the lattice itself; optimized, the springs' pull at the rims reaches a row or two in.
      const double within = optimize ? 0.015 : 0.01;
      EXPECT_GE(lo, 1 - within) << what;
      EXPECT_LE(hi, 1 + within) << what;
    }
}

INSTANTIATE_TEST_SUITE_P(TriAndGrid, SeamlessCylinder, ::testing::Values(Tessellation::Triangle, Tessellation::Grid),
                         [](const auto& info) { return std::string(enum_name(info.param)); });

TEST(SeamlessBand, RowsAcrossTheBandTurnTheLattice) {
  Design design;
  design.pattern.tessellation = Tessellation::Grid;
  design.pattern.spacing = 0.63;
  design.placement.band_rows = BandRows::Across;
  PavementOptions options;
  options.optimize = false;
  const Pavement across = make_pavement(cylinder_map(), design, options);
  ASSERT_TRUE(across.band_closure);
  EXPECT_TRUE(across.band_closure->rows_across);
  EXPECT_EQ(across.band_closure->step, glm::ivec2(0, 1));
  EXPECT_NEAR(std::abs(across.band_closure->rotation_deg), 90, 1e-9);
  const auto [lo, hi] = nearest_neighbour_range(across);
  EXPECT_GE(lo, 0.99);
  EXPECT_LE(hi, 1.01);
}

// Stones come in catalogue sizes: closing the band changes D, never the stones. The gap takes the
// change, so D may only grow (never below the design's gap); the elements' own diameters say so.
TEST(SeamlessBand, StonesKeepTheirSizeAndTheGapTakesTheChange) {
  for (const double stone : {0.5, 0.55, 0.6}) {
    Design design;
    design.pattern.tessellation = Tessellation::Triangle;
    design.elements.gap = 0.05;
    set_stone_size(design, stone);
    const Pavement p = make_pavement(cylinder_map(), design, {});
    ASSERT_TRUE(p.band_closure);
    const std::string what = "stone " + std::to_string(stone) + ": " + describe_band_closure(*p.band_closure);
    EXPECT_TRUE(p.band_closure->stones_kept) << what;
    EXPECT_GE(p.band_closure->spacing, stone + 0.05) << what;
    ASSERT_GT(p.elements.size(), 0u) << what;
    for (size_t i = 0; i < p.elements.size(); ++i) ASSERT_NEAR(p.elements.diameter[i], stone, 1e-12) << what;
    EXPECT_NEAR(p.design.elements.vertex.scale * p.design.pattern.spacing, stone, 1e-12) << what;
    EXPECT_EQ(p.after.contact_violations, 0) << what;
    EXPECT_GE(p.after.min_clearance, 0.05) << what;
  }
  // Spheres are sized with D, as everywhere: the closure may bring them closer.
  Design spheres;
  spheres.pattern.spacing = 0.63;
  const Pavement p = make_pavement(cylinder_map(), spheres, {});
  ASSERT_TRUE(p.band_closure);
  EXPECT_FALSE(p.band_closure->stones_kept);
}

// A band's pavement carries its closed design (design.json): paved again, that design closes the
// band at the same D with the same steps, and lays the same stones, not one step fewer.
TEST(SeamlessBand, ItsClosedDesignPavedAgainClosesAtTheSameSpacing) {
  for (const double stone : {0.5, 0.55, 0.6}) {
    Design design;
    design.pattern.tessellation = Tessellation::Triangle;
    design.elements.gap = 0.05;
    set_stone_size(design, stone);
    const Pavement first = make_pavement(cylinder_map(), design, {});
    const Pavement again = make_pavement(cylinder_map(), first.design, {});
    ASSERT_TRUE(first.band_closure && again.band_closure);
    const std::string what = "stone " + std::to_string(stone) + ": " + describe_band_closure(*first.band_closure) +
                             " then " + describe_band_closure(*again.band_closure);
    EXPECT_EQ(again.band_closure->around, first.band_closure->around) << what;
    EXPECT_EQ(again.design.pattern.spacing, first.design.pattern.spacing) << what;
    ASSERT_EQ(again.elements.size(), first.elements.size()) << what;
    for (size_t i = 0; i < first.elements.size(); ++i) {
      ASSERT_EQ(again.elements.position[i], first.elements.position[i]) << what << ", element " << i;
      ASSERT_EQ(again.elements.diameter[i], first.elements.diameter[i]) << what << ", element " << i;
    }
  }
}

// The smallest free space between the stones' footprints and a rim (3D, to the rim's polyline).
double clearance_to_rim(const SurfaceMesh& mesh, const std::vector<int>& loop, const Elements& e) {
  double clearance = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < e.size(); ++i)
    for (size_t k = 0; k < loop.size(); ++k) {
      const glm::dvec3 a = mesh.positions[loop[k]], b = mesh.positions[loop[(k + 1) % loop.size()]];
      const double t = std::clamp(glm::dot(e.position[i] - a, b - a) / glm::dot(b - a, b - a), 0.0, 1.0);
      clearance = std::min(clearance, glm::length(e.position[i] - (a + t * (b - a))) - 0.5 * e.diameter[i]);
    }
  return clearance;
}

TEST(SeamlessBand, TheRowsSitInTheMiddleBetweenTheRims) {
  // A jeweller's ring: 1.3 mm stones, 0.1 mm gap, no margin. The first shift that kept the most
  // rows left 0.03 mm to one rim and 0.49 mm to the other.
  Design design;
  design.pattern.tessellation = Tessellation::Triangle;
  design.elements.gap = 0.1;
  set_stone_size(design, 1.3);
  const auto ring = test::named_map("ring_band");
  const Pavement p = make_pavement(*ring, design, {});
  ASSERT_TRUE(p.band_closure);
  ASSERT_EQ(ring->mesh.boundary_loops.size(), 2u);
  const double one = clearance_to_rim(ring->mesh, ring->mesh.boundary_loops[0], p.elements);
  const double other = clearance_to_rim(ring->mesh, ring->mesh.boundary_loops[1], p.elements);
  EXPECT_GE(std::min(one, other), 0.0);
  // Within a sixteenth of a row (the shifts' step) of each other; rows are 1.4 x 0.87 mm apart.
  EXPECT_LT(std::abs(one - other), 1.4 * 0.87 / 16 * 1.5) << one << " and " << other;
}

TEST(SeamlessBand, TheAdaptivePatternPavesTheAnnulus) {
  Design design;
  design.pattern.topology = Topology::Adaptive;
  design.pattern.spacing = 0.63;
  PavementOptions options;
  options.optimize = false;
  const Pavement p = make_pavement(cylinder_map(), design, options);
  EXPECT_FALSE(p.seamless);
  EXPECT_FALSE(p.band_closure);
  EXPECT_EQ(&pavement_map(cylinder_map(), p), &cylinder_map());
}

}  // namespace
}  // namespace paver
