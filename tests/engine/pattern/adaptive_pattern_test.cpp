#include "pattern/adaptive_pattern.h"

#include "map/boundary_index.h"
#include "map/lifting.h"
#include "pattern/default_spacing.h"
#include "pipeline/pavement.h"
#include "core/input_error.h"

#include "input_error_assertions.h"
#include "surface_maps.h"
#include "test_meshes.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>

namespace paver {
namespace {

Design design_of(const SurfaceMap& map, Tessellation t) {
  Design d;
  d.pattern.tessellation = t;
  d.pattern.spacing = default_spacing(map.mesh, t);
  d.pattern.topology = Topology::Adaptive;
  return d;
}

TEST(AdaptivePattern, OnAFlatSquareTheParticlesFormARegularTriangleLattice) {
  const SurfaceMap map = build_surface_map(test::grid_surface(24, 24, [](double u, double v) {
    return glm::dvec3(u, v, 0);
  }));
  const Design design = design_of(map, Tessellation::Triangle);
  const AdaptivePattern adaptive = build_adaptive_pattern(map, make_design_cell(design.pattern), design);
  const Pattern& p = adaptive.pattern;
  ASSERT_GT(p.point_count(), 300);
  EXPECT_TRUE(p.crossing_edges.empty());  // grown inside the surface: no lattice edge crosses out
  const std::vector<glm::dvec3> xyz = test::lifted_positions(map, p.points);
  // Interior particles (farther than 1.5 D from the square's sides) with six neighbours.
  std::vector<int> valence(p.point_count(), 0);
  for (int e = 0; e < p.edge_count(); ++e) ++valence[p.edge_a[e]], ++valence[p.edge_b[e]];
  const double D = design.pattern.spacing;
  int interior = 0, regular = 0;
  std::vector<double> nearest(p.point_count(), 1e300);
  for (int e = 0; e < p.edge_count(); ++e) {
    const double l = glm::length(xyz[p.edge_a[e]] - xyz[p.edge_b[e]]);
    nearest[p.edge_a[e]] = std::min(nearest[p.edge_a[e]], l);
    nearest[p.edge_b[e]] = std::min(nearest[p.edge_b[e]], l);
  }
  double sum = 0, sum2 = 0;
  for (int i = 0; i < p.point_count(); ++i) {
    const glm::dvec3 x = xyz[i];
    if (std::min({x.x, x.y, 1 - x.x, 1 - x.y}) < 1.5 * D) continue;
    ++interior;
    regular += valence[i] == 6;
    sum += nearest[i], sum2 += nearest[i] * nearest[i];
  }
  ASSERT_GT(interior, 150);
  EXPECT_GE(double(regular) / interior, 0.9);
  const double mean = sum / interior, cv = std::sqrt(std::max(0.0, sum2 / interior - mean * mean)) / mean;
  EXPECT_LT(cv, 0.05);
  EXPECT_NEAR(mean, D, 0.1 * D);
  // The margin is kept to within a tenth of a radius (a corner pushes back along one side only);
  // the optimizer and the boundary elimination make it exact.
  for (const glm::dvec3& x : xyz) EXPECT_GE(std::min({x.x, x.y, 1 - x.x, 1 - x.y}), 0.45 * D);
}

TEST(AdaptivePattern, AHoneycombIsTheDualWithThreeEdgesAtEveryInnerPointAndFacesForDefects) {
  const auto map = test::cached_map(test::scanned_mesh("bunnyhead"));
  Design design = design_of(*map, Tessellation::Hexagon);
  const AdaptivePattern adaptive = build_adaptive_pattern(*map, make_design_cell(design.pattern), design);
  const Pattern& p = adaptive.pattern;
  std::vector<int> valence(p.point_count(), 0);
  for (int e = 0; e < p.edge_count(); ++e)
    if (!p.edge_virtual[e]) ++valence[p.edge_a[e]], ++valence[p.edge_b[e]];
  EXPECT_EQ(*std::max_element(valence.begin(), valence.end()), 3);
  const long three = std::count(valence.begin(), valence.end(), 3);
  EXPECT_GT(three, 0.8 * p.point_count());
  // Defects are the faces that are not hexagons: pentagons and heptagons, mostly.
  ASSERT_FALSE(p.defects.empty());
  for (const Pattern::Defect& d : p.defects) {
    EXPECT_NE(d.valence, 6);
    EXPECT_EQ(int(d.points.size()), d.valence);
  }
}

// The nearly closed bunny head: its map squeezes the ears (2D/3D area ratio down to 0.11 on the
// symmetric Dirichlet map; 20-fold on the ARAP map before it), so the lattice piles up and leaves
// bare patches. The adaptive pattern, packed to contact, covers it (issue 10's targets;
// docs/topology.md has the figures): fill >= 0.90, NN p95 <= 1.15, NN cv <= 0.05, with no contact
// violation and no removal after the pattern is built. Regular valence >= 85%: hex 0.93; tri
// 0.857 once defect healing cancels some of the dislocations that packing freezes in (0.849
// without it). The tri figure is near its bound: turning the seed lattice gives 0.807-0.857
// (docs/topology.md), so a change that moves it below 0.85 is one to measure, not to loosen.
struct HeadTargets {
  Tessellation tessellation;
  double least_regular_share;
};

class AdaptiveOnTheHead : public ::testing::TestWithParam<HeadTargets> {};

TEST_P(AdaptiveOnTheHead, ItCoversTheHeadRegularlyWithNoContact) {
  const auto map = test::cached_map(test::scanned_mesh("bunnyhead"));
  Design design = design_of(*map, GetParam().tessellation);
  const Pavement adaptive = make_pavement(*map, design);
  design.pattern.topology = Topology::Lattice;
  const Pavement lattice = make_pavement(*map, design);
  const PavementQuality& q = adaptive.after;
  EXPECT_EQ(q.contact_violations, 0);
  EXPECT_EQ(q.boundary_crossings, 0);
  EXPECT_EQ(adaptive.resolution.removed, 0);  // packed, not deleted
  EXPECT_GE(q.fill, 0.90);
  EXPECT_LE(q.neighbor_ratio.p95, 1.15);
  EXPECT_LE(q.neighbor_ratio.cv, 0.05);
  EXPECT_GT(q.interior_vertex_elements, 500);
  EXPECT_GE(q.regular_valence_share, GetParam().least_regular_share);
  if (GetParam().tessellation == Tessellation::Triangle) {  // packed to contact, then healed
    EXPECT_LT(adaptive.relaxation.healing.defects_after, adaptive.relaxation.healing.defects_before);
  }
  // The lattice on the same head: bare (on the ARAP map it was torn too; the symmetric
  // Dirichlet map keeps what it places regular, nearest-neighbour p95 1.10).
  EXPECT_LT(lattice.after.fill, 0.70);
}

INSTANTIATE_TEST_SUITE_P(TriAndHex, AdaptiveOnTheHead,
                         ::testing::Values(HeadTargets{Tessellation::Triangle, 0.85},
                                           HeadTargets{Tessellation::Hexagon, 0.85}));

// Vertex and edge gems (the bundled pendant_tri_gems design at the head's default spacing): each
// kind keeps 85% of its ideal count. The edge gems sit on the surface nearest their bar's 3D
// midpoint; at the map's midpoint (lifted) about 800 of them collided with a vertex gem.
TEST(AdaptivePattern, VertexAndEdgeGemsOnTheHeadEachKeepTheirCount) {
  const auto map = test::cached_map(test::scanned_mesh("bunnyhead"));
  Design design = design_of(*map, Tessellation::Triangle);
  design.elements.vertex = {true, 0.6, ShapeKind::Gem};
  design.elements.edge = {EdgeElementDesign{0.5, 0.35, ShapeKind::Gem, {}}};
  const Pavement p = make_pavement(*map, design);
  EXPECT_EQ(p.after.contact_violations, 0);
  EXPECT_EQ(p.after.boundary_crossings, 0);
  EXPECT_LT(p.paper.contact_violations, long(0.01 * p.paper.elements));
  EXPECT_GE(p.after.vertex_fill, 0.85);
  EXPECT_GE(p.after.edge_fill, 0.85);
}

Design stones_of(double stone, double gap, double margin) {
  Design d;
  d.pattern.tessellation = Tessellation::Triangle;
  d.pattern.topology = Topology::Adaptive;
  d.elements.gap = gap;
  d.elements.margin = margin;
  set_stone_size(d, stone);
  return d;
}

// The particles keep the edge margin: they were kept a radius from the rims only, so every one in
// the margin's strip was placed and then eliminated at the boundary, leaving a bare ring inside
// each rim and hole (the pierced pendant: 87 eliminated, 67 bare spots).
TEST(AdaptivePattern, TheParticlesKeepTheEdgeMarginSoNoRimRowIsEliminated) {
  const SurfaceMap& map = *test::bundled_map("pendant_pierced");
  const Pavement p = make_pavement(map, stones_of(1.5, 0.1, 0.3));
  EXPECT_EQ(p.eliminated, 0);
  EXPECT_EQ(p.after.boundary_crossings, 0);
  EXPECT_LE(p.after.edges.bare_spots, 3);
  EXPECT_GT(p.elements.size(), 320u);
}

// A narrow band whose width holds a fraction of a row too many stays jammed through the packing's
// rounds: the ring band at 1.25 mm went to the optimizer with ~300 pairs overlapping and lost 123
// stones still colliding. The extra rounds take out what does not fit, and the rest is spread again.
TEST(AdaptivePattern, AnOverfullNarrowBandIsThinnedAndSpreadNotLeftJammed) {
  const SurfaceMap& map = *test::bundled_map("ring_band");
  const Pavement p = make_pavement(map, stones_of(1.25, 0.1, 0.2));
  EXPECT_EQ(p.resolution.removed, 0);
  EXPECT_EQ(p.after.contact_violations, 0);
  EXPECT_GT(p.elements.size(), 190u);
  EXPECT_LE(p.after.edges.bare_spots, 3);
}

TEST(AdaptivePattern, DesignsItCannotTakeAreRefusedNamingTheKey) {
  Design grid;
  grid.pattern.tessellation = Tessellation::Grid;
  grid.pattern.topology = Topology::Adaptive;
  EXPECT_TRUE(test::Contains(test::error_of([&] { check_design_cell(grid); }), "pattern.topology"));
  Design one_direction;
  one_direction.pattern.tessellation = Tessellation::Triangle;
  one_direction.pattern.topology = Topology::Adaptive;
  one_direction.elements.vertex.scale = 0.5;
  one_direction.elements.edge.push_back({0.5, 0.3, ShapeKind::Sphere, {0}});
  EXPECT_TRUE(test::Contains(test::error_of([&] { check_design_cell(one_direction); }), "some edges only"));
  Design lopsided;
  lopsided.pattern.tessellation = Tessellation::Hexagon;
  lopsided.elements.edge.push_back({0.3, 0.3, ShapeKind::Sphere, {}});
  EXPECT_NE(adaptive_pattern_unsupported(lopsided), "");
  lopsided.elements.edge.push_back({0.7, 0.3, ShapeKind::Sphere, {}});
  EXPECT_EQ(adaptive_pattern_unsupported(lopsided), "");
}

}  // namespace
}  // namespace paver
