// Tests for engine/pipeline/pavement.cpp (with element_placement.cpp and default_spacing.cpp): a design
// becomes a unit cell, a pattern and elements on the surface; design mistakes are refused with
// the key that holds them.
#include "pattern/default_spacing.h"
#include "design/design.h"
#include "core/input_error.h"
#include "mesh/mesh_loader.h"
#include "pipeline/pavement.h"
#include "map/surface_map.h"
#include "mesh/surface_mesh.h"
#include "pattern/unit_cell.h"

#include "input_error_assertions.h"

#include "surface_maps.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <set>
#include <string>
#include <vector>

namespace paver {
namespace {

using test::Contains;
using test::error_of;

// The dome is a cap of the sphere of radius 100 centred at (0, 0, -50), top at z = 50
// (assets/surfaces/README.md).
const glm::dvec3 kDomeCentre(0, 0, -50);
constexpr double kDomeRadius = 100;

const SurfaceMap& dome_map() { return *test::bundled_map("dome"); }

bool inside_map(const SurfaceMap& map, glm::dvec2 p) {
  bool in = false;
  const std::vector<int>& loop = map.mesh.outer_loop();
  for (size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
    const glm::dvec2 a = map.uv[loop[i]], b = map.uv[loop[j]];
    if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) in = !in;
  }
  return in;
}

// How far inside the sphere the dome's triangles reach: a flat triangle with its corners on the
// sphere is deepest at its circumcentre, R - sqrt(R^2 - r^2) for circumradius r.
double dome_sag() {
  const SurfaceMesh& mesh = dome_map().mesh;
  double sag = 0;
  for (const glm::ivec3& t : mesh.triangles) {
    const glm::dvec3 p = mesh.positions[t.x], q = mesh.positions[t.y], r = mesh.positions[t.z];
    const double a = glm::length(q - p), b = glm::length(r - q), c = glm::length(p - r);
    const double circumradius = a * b * c / (2 * glm::length(glm::cross(q - p, r - p)));
    sag = std::max(sag, kDomeRadius - std::sqrt(kDomeRadius * kDomeRadius - circumradius * circumradius));
  }
  return sag;
}

// Every element sits on the dome with the dome's outward normal.
void expect_on_the_dome(const Elements& elements) {
  ASSERT_EQ(elements.position.size(), elements.size());
  ASSERT_EQ(elements.normal.size(), elements.size());
  const double sag = dome_sag();
  ASSERT_LT(sag, 0.2);
  for (size_t i = 0; i < elements.size(); ++i) {
    const glm::dvec3 radial = elements.position[i] - kDomeCentre;
    EXPECT_LE(glm::length(radial), kDomeRadius + 1e-6) << "element " << i;
    EXPECT_GE(glm::length(radial), kDomeRadius - sag - 1e-6) << "element " << i;
    EXPECT_GE(elements.position[i].z, -1e-9) << "element " << i;
    EXPECT_NEAR(glm::length(elements.normal[i]), 1.0, 1e-9) << "element " << i;
    EXPECT_GT(glm::dot(elements.normal[i], glm::normalize(radial)), 0.99) << "element " << i;
  }
}

Design design_with(Tessellation tessellation, double spacing) {
  Design design;
  design.pattern.tessellation = tessellation;
  design.pattern.spacing = spacing;
  return design;
}

// The stages these tests cover: pattern and element placement, without the section 5 optimizer
// and the section 5.4 post-processing (pavement_optimization_test.cpp covers those).
PavementOptions placement_only() {
  PavementOptions options;
  options.optimize = false;
  options.postprocess = false;
  return options;
}

Pavement place_only(const SurfaceMap& map, const Design& design) { return make_pavement(map, design, placement_only()); }

EdgeOperator make_operator(EdgeOperator::Kind kind, int from, int to, glm::ivec2 offset) {
  EdgeOperator op;
  op.kind = kind, op.from = from, op.to = to, op.offset = offset;
  return op;
}

TEST(PavementDefaults, SpacingZeroResolvesToAboutAThousandPoints) {
  const SurfaceMap& dome = dome_map();
  const Design design;  // hexagonal, spacing 0, V-elements only, bracing on
  ASSERT_EQ(design.pattern.spacing, 0);
  const Pavement pavement = place_only(dome, design);

  const double d = pavement.design.pattern.spacing;
  EXPECT_EQ(d, default_spacing(dome.mesh, Tessellation::Hexagon));
  // 1000 points at 2 per hexagonal cell of area 3 sqrt(3) / 2 D^2, rounded to two digits.
  const double exact = std::sqrt(surface_area(dome.mesh) * 2 / (1.5 * std::sqrt(3.0)) / 1000);
  EXPECT_NEAR(d, exact, 0.05 * exact);
  const double digit = std::pow(10.0, std::floor(std::log10(d)) - 1);
  EXPECT_NEAR(d / digit, std::round(d / digit), 1e-9) << d << " has more than two significant digits";
  EXPECT_EQ(pavement.cell.spacing, d);

  EXPECT_NEAR(pavement.pattern.point_count(), 1000, 200);
  EXPECT_EQ(pavement.points.size(), pavement.pattern.points.size());
  // Hexagon with bracing: 3 edges and 3 long diagonals.
  EXPECT_EQ(pavement.cell.edges.size(), 6u);
  ASSERT_GE(pavement.timings.size(), 1u);
  EXPECT_EQ(pavement.timings[0].first, "pattern");
}

TEST(PavementDefaults, DefaultSpacingFollowsTheTessellation) {
  // Same number of points: D^2 proportional to the area per point of each cell at D = 1
  // (tri sqrt(3)/2, grid 1, hex 3 sqrt(3) / 4), up to the two-digit rounding.
  const SurfaceMesh& mesh = dome_map().mesh;
  const double area = surface_area(mesh);
  const struct {
    Tessellation t;
    double area_per_point;
  } cases[] = {{Tessellation::Triangle, std::sqrt(3.0) / 2}, {Tessellation::Grid, 1}, {Tessellation::Hexagon, 0.75 * std::sqrt(3.0)}};
  for (const auto& c : cases) {
    const double exact = std::sqrt(area / (500 * c.area_per_point));
    EXPECT_NEAR(default_spacing(mesh, c.t, 500), exact, 0.05 * exact) << enum_name(c.t);
  }
}

TEST(PavementDefaults, AGivenSpacingIsKept) {
  const Pavement pavement = place_only(dome_map(), design_with(Tessellation::Grid, 7));
  EXPECT_EQ(pavement.design.pattern.spacing, 7);
  EXPECT_EQ(pavement.cell.spacing, 7);
  EXPECT_EQ(pavement.cell.tessellation, Tessellation::Grid);
}

TEST(PavementElements, OneVElementPerPoint) {
  Design design = design_with(Tessellation::Hexagon, 6);
  design.elements.vertex.scale = 0.8;
  design.elements.vertex.shape = ShapeKind::Gem;
  const Pavement pavement = place_only(dome_map(), design);
  const Elements& elements = pavement.elements;
  ASSERT_EQ(int(elements.size()), pavement.pattern.point_count());
  ASSERT_GT(elements.size(), 0u);
  for (size_t i = 0; i < elements.size(); ++i) {
    EXPECT_EQ(elements.kind[i], ElementKind::Vertex);
    EXPECT_EQ(elements.source[i], int(i));
    EXPECT_EQ(elements.uv[i], pavement.points[i]);
    EXPECT_DOUBLE_EQ(elements.diameter[i], 0.8 * 6);
    EXPECT_EQ(elements.shape[i], ShapeKind::Gem);
  }
  expect_on_the_dome(elements);
}

TEST(PavementElements, OneEElementPerRealEdgeWhoseCentreIsOnTheSurface) {
  Design design = design_with(Tessellation::Hexagon, 6);
  design.elements.vertex.enabled = false;
  EdgeElementDesign spec;
  spec.t = 0.5, spec.scale = 0.3;
  design.elements.edge = {spec};
  const Pavement pavement = place_only(dome_map(), design);
  const Pattern& pattern = pavement.pattern;
  const Elements& elements = pavement.elements;

  int real_edges = 0, expected = 0;
  for (int e = 0; e < pattern.edge_count(); ++e) {
    if (pattern.edge_virtual[e]) continue;
    ++real_edges;
    const glm::dvec2 mid = 0.5 * (pattern.points[pattern.edge_a[e]] + pattern.points[pattern.edge_b[e]]);
    expected += inside_map(dome_map(), mid) ? 1 : 0;
  }
  ASSERT_GT(real_edges, 0);
  EXPECT_LT(real_edges, pattern.edge_count()) << "bracing should have added virtual edges";
  EXPECT_EQ(int(elements.size()), expected);
  EXPECT_GE(expected, real_edges - 10);

  std::set<int> sources;
  for (size_t i = 0; i < elements.size(); ++i) {
    EXPECT_EQ(elements.kind[i], ElementKind::Edge);
    EXPECT_EQ(elements.spec[i], 0);
    const int e = elements.source[i];
    ASSERT_GE(e, 0);
    ASSERT_LT(e, pattern.edge_count());
    EXPECT_FALSE(pattern.edge_virtual[e]) << "E-element on a virtual edge";
    EXPECT_TRUE(sources.insert(e).second) << "two E-elements on edge " << e;
    const glm::dvec2 mid = 0.5 * (pattern.points[pattern.edge_a[e]] + pattern.points[pattern.edge_b[e]]);
    EXPECT_LE(glm::length(elements.uv[i] - mid), 1e-12 * 6);
    EXPECT_DOUBLE_EQ(elements.diameter[i], 0.3 * 6);
  }
  expect_on_the_dome(elements);
}

TEST(PavementElements, EElementsSitAtTheirT) {
  Design design = design_with(Tessellation::Triangle, 8);
  design.elements.vertex.enabled = false;
  EdgeElementDesign near_from, near_to;
  near_from.t = 0.25, near_to.t = 0.9, near_to.scale = 0.2, near_to.shape = ShapeKind::Disc;
  design.elements.edge = {near_from, near_to};
  design.elements.allow_overlap = true;  // the two specs overlap by design; placement is what is tested
  const Pavement pavement = place_only(dome_map(), design);
  const Pattern& pattern = pavement.pattern;
  int per_spec[2] = {0, 0};
  for (size_t i = 0; i < pavement.elements.size(); ++i) {
    const int s = pavement.elements.spec[i], e = pavement.elements.source[i];
    ASSERT_TRUE(s == 0 || s == 1);
    ++per_spec[s];
    const glm::dvec2 a = pattern.points[pattern.edge_a[e]], b = pattern.points[pattern.edge_b[e]];
    const double t = s == 0 ? 0.25 : 0.9;
    EXPECT_LE(glm::length(pavement.elements.uv[i] - (a + t * (b - a))), 1e-12 * 8);
    EXPECT_DOUBLE_EQ(pavement.elements.diameter[i], (s == 0 ? 0.5 : 0.2) * 8);
    EXPECT_EQ(pavement.elements.shape[i], s == 0 ? ShapeKind::Sphere : ShapeKind::Disc);
  }
  // Triangles need no bracing: every edge is real and carries one element of each spec, less the
  // few whose point is off a boundary that bends inwards.
  EXPECT_NEAR(per_spec[0], pattern.edge_count(), 0.02 * pattern.edge_count());
  EXPECT_NEAR(per_spec[1], pattern.edge_count(), 0.02 * pattern.edge_count());
  expect_on_the_dome(pavement.elements);
}

TEST(PavementElements, CellEdgesRestrictAnEElementToOneEdgeOfTheCell) {
  Design design = design_with(Tessellation::Hexagon, 6);
  design.elements.vertex.enabled = false;
  EdgeElementDesign everywhere;
  design.elements.edge = {everywhere};
  const Pavement all = place_only(dome_map(), design);

  EdgeElementDesign first_edge;
  first_edge.cell_edges = {0};
  design.elements.edge = {first_edge};
  const Pavement restricted = place_only(dome_map(), design);
  const Pattern& pattern = restricted.pattern;

  int expected = 0;
  for (int e = 0; e < pattern.edge_count(); ++e)
    if (pattern.edge_cell_edge[e] == 0) {
      const glm::dvec2 mid = 0.5 * (pattern.points[pattern.edge_a[e]] + pattern.points[pattern.edge_b[e]]);
      expected += inside_map(dome_map(), mid) ? 1 : 0;
    }
  EXPECT_EQ(int(restricted.elements.size()), expected);
  for (size_t i = 0; i < restricted.elements.size(); ++i)
    EXPECT_EQ(pattern.edge_cell_edge[restricted.elements.source[i]], 0);
  // The honeycomb's three edge directions are equally common.
  const double share = double(restricted.elements.size()) / double(all.elements.size());
  EXPECT_NEAR(share, 1.0 / 3, 0.05);
}

TEST(PavementErrors, CellEdgeOutOfRangeNamesTheKey) {
  Design design = design_with(Tessellation::Hexagon, 6);
  EdgeElementDesign spec;
  spec.cell_edges = {6};  // hexagon + bracing has edges 0..5
  design.elements.edge = {spec};
  std::string message = error_of([&] { place_only(dome_map(), design); });
  EXPECT_TRUE(Contains(message, "elements.edge[0].cell_edges"));
  EXPECT_TRUE(Contains(message, "0..5"));

  spec.cell_edges = {0, -1};
  design.elements.edge = {EdgeElementDesign{}, spec};
  message = error_of([&] { place_only(dome_map(), design); });
  EXPECT_TRUE(Contains(message, "elements.edge[1].cell_edges"));

  // Without bracing the long diagonals are not there.
  design.pattern.bracing = false;
  spec.cell_edges = {3};
  design.elements.edge = {spec};
  message = error_of([&] { place_only(dome_map(), design); });
  EXPECT_TRUE(Contains(message, "elements.edge[0].cell_edges"));
  EXPECT_TRUE(Contains(message, "0..2"));
}

TEST(PavementErrors, FailingOperatorNamesItsIndex) {
  Design design = design_with(Tessellation::Hexagon, 6);
  design.pattern.operators = {make_operator(EdgeOperator::Kind::Remove, 0, 0, {0, 1})};
  std::string message = error_of([&] { place_only(dome_map(), design); });
  EXPECT_TRUE(Contains(message, "pattern.operators[0]"));
  EXPECT_TRUE(Contains(message, "remove 0->0 @ (0,1)"));

  // The second of two operators: the first one succeeds, so the index points at the culprit.
  design.pattern.operators = {make_operator(EdgeOperator::Kind::Remove, 0, 1, {0, 0}),
                              make_operator(EdgeOperator::Kind::Remove, 1, 0, {0, 0})};
  message = error_of([&] { make_design_cell(design.pattern); });
  EXPECT_TRUE(Contains(message, "pattern.operators[1]"));
  EXPECT_FALSE(Contains(message, "pattern.operators[0]"));
}

TEST(PavementCell, OperatorsAndBracingReachThePattern) {
  // Grid plus a diagonal: triangles, so no bracing; the diagonal springs rest at D sqrt(2).
  PatternDesign pattern;
  pattern.tessellation = Tessellation::Grid;
  pattern.spacing = 5;
  pattern.operators = {make_operator(EdgeOperator::Kind::Add, 0, 0, {1, 1})};
  const UnitCell cell = make_design_cell(pattern);
  ASSERT_EQ(cell.edges.size(), 3u);
  for (const CellEdge& e : cell.edges) EXPECT_FALSE(e.is_virtual);

  Design design = design_with(Tessellation::Grid, 5);
  design.pattern.operators = pattern.operators;
  const Pavement pavement = place_only(dome_map(), design);
  int diagonals = 0;
  for (int e = 0; e < pavement.pattern.edge_count(); ++e) {
    EXPECT_FALSE(pavement.pattern.edge_virtual[e]);
    if (pavement.pattern.edge_cell_edge[e] == 2) {
      ++diagonals;
      EXPECT_NEAR(pavement.pattern.edge_rest_length[e], 5 * std::sqrt(2.0), 1e-12);
    }
  }
  EXPECT_GT(diagonals, 0);

  // The plain grid is braced by both diagonals, as virtual springs.
  design.pattern.operators.clear();
  const Pavement braced = place_only(dome_map(), design);
  ASSERT_EQ(braced.cell.edges.size(), 4u);
  int virtual_edges = 0;
  for (std::uint8_t v : braced.pattern.edge_virtual) virtual_edges += v;
  EXPECT_GT(virtual_edges, 0);
  design.pattern.bracing = false;
  EXPECT_EQ(place_only(dome_map(), design).cell.edges.size(), 2u);
}

// Topology auto (the default) keeps the paper's lattice wherever it works, and grows the pattern
// on the surface where the lattice measurably tears or leaves bare patches (issue 10): the user
// gets the cover without knowing the flag.
TEST(PavementTopologyAuto, KeepsTheLatticeWhereItWorks) {
  Design lattice;
  lattice.pattern.topology = Topology::Lattice;
  Design automatic;
  ASSERT_EQ(automatic.pattern.topology, Topology::Auto) << "auto is the default";
  const Pavement a = make_pavement(dome_map(), lattice), b = make_pavement(dome_map(), automatic);
  EXPECT_EQ(b.design.pattern.topology, Topology::Lattice);
  EXPECT_NE(b.topology_choice.find("auto: lattice"), std::string::npos) << b.topology_choice;
  EXPECT_EQ(a.elements.position, b.elements.position) << "auto on a surface the lattice paves is the lattice";
  EXPECT_TRUE(a.topology_choice.empty());
}

TEST(PavementTopologyAuto, GrowsThePatternWhereTheLatticeTears) {
  const auto head = test::cached_map(test::scanned_mesh("bunnyhead"));
  for (const Tessellation tessellation : {Tessellation::Triangle, Tessellation::Hexagon}) {
    Design design;
    design.pattern.tessellation = tessellation;
    Design lattice = design;
    lattice.pattern.topology = Topology::Lattice;
    const Pavement torn = make_pavement(*head, lattice);
    ASSERT_LT(torn.after.fill, 0.85) << "the lattice leaves bare patches on the head";
    const Pavement p = make_pavement(*head, design);
    EXPECT_EQ(p.design.pattern.topology, Topology::Adaptive) << p.topology_choice;
    EXPECT_NE(p.topology_choice.find("auto: adaptive; the lattice"), std::string::npos) << p.topology_choice;
    EXPECT_GE(p.after.fill, 0.90);
    EXPECT_EQ(p.after.contact_violations, 0);
    EXPECT_EQ(p.after.boundary_crossings, 0);
    EXPECT_EQ(p.timings.front().first, "lattice_tried") << "the lattice's time is part of the run's";
  }
}

TEST(PavementTopologyAuto, KeepsTheLatticeForADesignTheAdaptivePatternCannotTake) {
  const auto head = test::cached_map(test::scanned_mesh("bunnyhead"));
  Design grid;
  grid.pattern.tessellation = Tessellation::Grid;  // no adaptive grid: the lattice stays, and says why
  const Pavement p = make_pavement(*head, grid);
  EXPECT_EQ(p.design.pattern.topology, Topology::Lattice);
  EXPECT_NE(p.topology_choice.find("cannot take this design"), std::string::npos) << p.topology_choice;
}

}  // namespace
}  // namespace paver
