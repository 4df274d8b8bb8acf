// Tests for engine/report/pavement_quality.cpp: measure_pavement on hand-made element sets over a
// flat 100 x 100 square, where every figure is known in advance: element counts by kind, the
// collision count and worst overlap (0.99 (r_i + r_j) rule, mixed diameters, coincident centres),
// the nearest-neighbour ratio distribution (min, p5, median, p95, max, mean, cv), boundary
// crossings, coverage and the spring-length deviation of a hand-made pattern; then the JSON form
// and the ratio colour scale.
#include "report/pavement_quality.h"

#include "map/surface_map.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <numeric>
#include <vector>

namespace paver {
namespace {

constexpr double kSide = 100;

// The square [0, 100]^2 at z = 0; flat, so its map is an isometry and its curvature is zero.
const SurfaceMap& flat_map() {
  static const SurfaceMap map = build_surface_map(
      test::grid_surface(4, 4, [](double u, double v) { return glm::dvec3(kSide * u, kSide * v, 0); }));
  return map;
}

void add(Elements& e, double x, double y, double diameter, ElementKind kind = ElementKind::Vertex) {
  // uv: any point of the map (only the curvature correlation lifts it, and the square is flat).
  const glm::dvec2 uv = 0.5 * (flat_map().uv_min + flat_map().uv_max);
  e.push_back(kind, int(e.size()), 0, uv, {x, y, 0}, {0, 0, 1}, diameter, ShapeKind::Sphere);
}

// Groups far apart from each other (diameter 2 unless said), each with known ratios:
//   chain 10, 12, 15             ratios 1, 1, 1.5
//   pair 1.6 apart               0.8, 0.8   collision, overlap 0.2
//   pair 2.4 apart               1.2, 1.2
//   diameters 2 and 1, 1.35 apart  0.9, 0.9  collision, overlap 0.1
//   pair 1.99 apart              0.995, 0.995 collision, overlap 0.005 (the rule forgives nothing)
//   diameters 2 and 1, one centre  0, 0      collision, overlap 1
//   pair 0.9 from the boundary   1, 1       the first crosses the boundary
//   pair 1.1 from the boundary   1, 1       neither crosses
Elements known_set() {
  Elements e;
  add(e, 10, 50, 2), add(e, 12, 50, 2), add(e, 15, 50, 2);
  add(e, 30, 50, 2), add(e, 31.6, 50, 2);
  add(e, 50, 50, 2), add(e, 52.4, 50, 2);
  add(e, 70, 50, 2), add(e, 71.35, 50, 1, ElementKind::Edge);
  add(e, 50, 20, 2, ElementKind::Edge), add(e, 51.99, 20, 2, ElementKind::Edge);
  add(e, 80, 80, 2), add(e, 80, 80, 1, ElementKind::Edge);
  add(e, 0.9, 30, 2), add(e, 2.9, 30, 2);
  add(e, 1.1, 70, 2), add(e, 3.1, 70, 2);
  return e;
}

const std::vector<double> kKnownRatios = {1, 1, 1.5, 0.8, 0.8, 1.2, 1.2, 0.9, 0.9, 0.995, 0.995, 0, 0, 1, 1, 1, 1};

PavementQuality measure(const Elements& elements) {
  return measure_pavement(flat_map(), Pattern{}, {}, elements, QualityBasis{});
}

TEST(PavementQualityJson, NoInteriorElementsMeansNoValenceShare) {
  // A narrow ring has none: a share of 0 read as "every stone a defect" in report.html.
  PavementQuality q;
  q.structure_measured = true;
  q.interior_vertex_elements = 0;
  EXPECT_TRUE(to_json(q)["regular_valence_share"].is_null());
  q.interior_vertex_elements = 10;
  q.regular_valence_share = 0.9;
  EXPECT_DOUBLE_EQ(to_json(q)["regular_valence_share"].get<double>(), 0.9);
}

TEST(PavementQualityKnownSet, CountsElementsByKind) {
  const PavementQuality q = measure(known_set());
  EXPECT_EQ(q.elements, 17);
  EXPECT_EQ(q.vertex_elements, 13);
  EXPECT_EQ(q.edge_elements, 4);
}

TEST(PavementQualityKnownSet, CountsCollisionsAndTheWorstOverlap) {
  const PavementQuality q = measure(known_set());
  EXPECT_EQ(q.contact_violations, 4);
  EXPECT_DOUBLE_EQ(q.worst_overlap, 1) << "the pair on one centre";
  EXPECT_DOUBLE_EQ(q.min_clearance, -1.5) << "the pair on one centre: radii 1 and 0.5";

  // Without the coincident pair the worst is the pair 1.6 apart: 1 - 1.6 / 2.
  Elements e;
  add(e, 30, 50, 2), add(e, 31.6, 50, 2);
  add(e, 70, 50, 2), add(e, 71.35, 50, 1);
  add(e, 50, 20, 2), add(e, 51.99, 20, 2);
  const PavementQuality q2 = measure(e);
  EXPECT_EQ(q2.contact_violations, 3);
  EXPECT_NEAR(q2.worst_overlap, 0.2, 1e-12);
  EXPECT_NEAR(q2.min_clearance, -0.4, 1e-12);

  // With a gap of 0.5 the pair 2.4 apart (clearance 0.4) violates too; 2.5 apart does not.
  Elements spaced;
  add(spaced, 30, 50, 2), add(spaced, 32.4, 50, 2);
  add(spaced, 60, 50, 2), add(spaced, 62.5, 50, 2);
  QualityBasis basis;
  basis.gap = 0.5;
  const PavementQuality q3 = measure_pavement(flat_map(), Pattern{}, {}, spaced, basis);
  EXPECT_EQ(q3.contact_violations, 1);
  EXPECT_EQ(q3.gap, 0.5);
  EXPECT_NEAR(q3.worst_overlap, 1 - 2.4 / 2.5, 1e-12);
  EXPECT_NEAR(q3.min_clearance, 0.4, 1e-12);
}

TEST(PavementQualityKnownSet, FillCountsAgainstTheIdealDensity) {
  // 100 x 100 square, 1 element per 10 x 10 cell, strip of 1 along a boundary 400 long: ideal 96.
  QualityBasis basis;
  basis.area_per_element = 100;
  basis.boundary_strip = 1;
  EXPECT_NEAR(ideal_element_count(flat_map(), basis), (kSide * kSide - 400) / 100, 1e-9);
  basis.ideal_count = ideal_element_count(flat_map(), basis);
  Elements e;
  for (int i = 0; i < 48; ++i) add(e, 5 + 10 * (i % 8), 5 + 10 * (i / 8), 2);
  const PavementQuality q = measure_pavement(flat_map(), Pattern{}, {}, e, basis);
  EXPECT_NEAR(q.fill, 0.5, 1e-9);
  EXPECT_EQ(measure(e).fill, 0) << "no basis, no fill";
}

TEST(PavementQualityKnownSet, NeighbourRatioDistribution) {
  const Distribution d = measure(known_set()).neighbor_ratio;
  // Sorted: 0 0 0.8 0.8 0.9 0.9 0.995 0.995 1 1 1 1 1 1 1.2 1.2 1.5 (17 values); percentiles
  // interpolate between ranks: p5 at rank 0.8, p95 at rank 15.2.
  EXPECT_NEAR(d.min, 0, 1e-12);
  EXPECT_NEAR(d.p5, 0, 1e-12);
  EXPECT_NEAR(d.median, 1, 1e-12);
  EXPECT_NEAR(d.p95, 1.2 + 0.2 * (1.5 - 1.2), 1e-12);
  EXPECT_NEAR(d.max, 1.5, 1e-12);
  const double mean = 15.29 / 17;
  EXPECT_NEAR(d.mean, mean, 1e-12);
  double var = 0;
  for (double r : kKnownRatios) var += (r - mean) * (r - mean);
  EXPECT_NEAR(d.cv, std::sqrt(var / 17) / mean, 1e-12);
}

TEST(PavementQualityKnownSet, BoundaryCrossingsAndCoverage) {
  const PavementQuality q = measure(known_set());
  EXPECT_EQ(q.boundary_crossings, 1);
  // 15 discs of diameter 2 and 2 of diameter 1 over the 100 x 100 square.
  EXPECT_NEAR(q.coverage, std::numbers::pi / 4 * (15 * 4 + 2 * 1) / (kSide * kSide), 1e-12);
  EXPECT_EQ(q.spacing_curvature_spearman, 0) << "the square is flat";
}

TEST(PavementQualityKnownSet, EmptyAndLoneElementSetsMeasureZero) {
  const PavementQuality none = measure(Elements{});
  EXPECT_EQ(none.elements, 0);
  EXPECT_EQ(none.contact_violations, 0);
  EXPECT_EQ(none.worst_overlap, 0);
  EXPECT_EQ(none.neighbor_ratio.max, 0);
  EXPECT_EQ(none.coverage, 0);

  Elements one;
  add(one, 50, 50, 4);
  const PavementQuality q = measure(one);
  EXPECT_EQ(q.elements, 1);
  EXPECT_EQ(q.contact_violations, 0);
  // Its ratio is +inf, which a distribution leaves out.
  EXPECT_EQ(q.neighbor_ratio.max, 0);
  EXPECT_EQ(q.neighbor_ratio.mean, 0);
}

TEST(PavementQualitySprings, DeviationFromTheRestLengthOverRealEdgesInUse) {
  // Four points 10 apart from the first (the map is an isometry of the flat square, so 3D lengths
  // equal uv lengths), edges with rest lengths 10, 8 and 12.5 (ratios 1, 1.25, 0.8), a virtual edge
  // and an edge to a retired point, both left out. c = m = 0: the target length is the rest length.
  const SurfaceMap& map = flat_map();
  const glm::dvec2 c = 0.5 * (map.uv_min + map.uv_max);
  Pattern pattern;
  pattern.points = {c, c + glm::dvec2(10, 0), c + glm::dvec2(0, 10), c + glm::dvec2(-6, 8), c + glm::dvec2(0, -10)};
  pattern.edge_a = {0, 0, 0, 1, 0};
  pattern.edge_b = {1, 2, 3, 2, 4};
  pattern.edge_rest_length = {10, 8, 12.5, 1, 1};
  pattern.edge_virtual = {0, 0, 0, 1, 0};
  pattern.edge_cell_edge = {0, 0, 0, 0, 0};
  const std::vector<std::uint8_t> retired = {0, 0, 0, 0, 1};

  const std::vector<double> ratios = spring_length_ratios(map, pattern, pattern.points, SolverParams{}, &retired);
  ASSERT_EQ(ratios.size(), 3u);
  EXPECT_NEAR(ratios[0], 1, 1e-6);
  EXPECT_NEAR(ratios[1], 1.25, 1e-6);
  EXPECT_NEAR(ratios[2], 0.8, 1e-6);

  const PavementQuality q = measure_pavement(map, pattern, pattern.points, Elements{}, QualityBasis{}, &retired);
  // Deviations 0, 0.25, 0.2: median 0.2, p95 at rank 1.9 = 0.2 + 0.9 * 0.05.
  EXPECT_NEAR(q.spring_deviation_median, 0.2, 1e-6);
  EXPECT_NEAR(q.spring_deviation_p95, 0.245, 1e-6);
}

TEST(PavementQualityJson, HoldsEveryFigure) {
  const PavementQuality q = measure(known_set());
  const nlohmann::json j = to_json(q);
  EXPECT_EQ(j["elements"].get<long>(), 17);
  EXPECT_EQ(j["vertex_elements"].get<long>(), 13);
  EXPECT_EQ(j["edge_elements"].get<long>(), 4);
  EXPECT_EQ(j["contact_violations"].get<long>(), 4);
  EXPECT_EQ(j["min_clearance"].get<double>(), q.min_clearance);
  EXPECT_EQ(j["gap"].get<double>(), 0);
  EXPECT_EQ(j["fill"].get<double>(), q.fill);
  EXPECT_EQ(j["worst_overlap"].get<double>(), q.worst_overlap);
  EXPECT_EQ(j["boundary_crossings"].get<long>(), 1);
  EXPECT_EQ(j["coverage"].get<double>(), q.coverage);
  for (const char* key : {"min", "p5", "median", "p95", "max", "mean", "cv"}) ASSERT_TRUE(j["neighbor_ratio"].contains(key)) << key;
  EXPECT_EQ(j["neighbor_ratio"]["p95"].get<double>(), q.neighbor_ratio.p95);
  EXPECT_EQ(j["neighbor_ratio"]["cv"].get<double>(), q.neighbor_ratio.cv);
}

TEST(PavementQualityColours, FollowThePapersScale) {
  using Rgb = std::array<std::uint8_t, 3>;
  const std::vector<Rgb> c =
      neighbor_ratio_colours({0.5, 0.90, 0.9999, 1.0, 1.3, 5.0, std::numeric_limits<double>::infinity(), 0.99995});
  EXPECT_EQ(c[0], (Rgb{215, 25, 28})) << "too close: red";
  EXPECT_EQ(c[1], (Rgb{215, 25, 28}));
  EXPECT_EQ(c[2], (Rgb{254, 224, 139})) << "just short of the required distance: yellow";
  EXPECT_EQ(c[3], (Rgb{26, 152, 80})) << "touching: dark green";
  EXPECT_EQ(c[4], (Rgb{199, 233, 160})) << "loose: light green";
  EXPECT_EQ(c[5], c[4]);
  EXPECT_EQ(c[6], c[4]) << "alone counts as loose";
  // Half way between yellow (254, 224, 139) and dark green (26, 152, 80), give or take rounding.
  EXPECT_NEAR(c[7][0], 140, 1);
  EXPECT_NEAR(c[7][1], 188, 1);
  EXPECT_NEAR(c[7][2], 109.5, 1);
}

}  // namespace
}  // namespace paver
