// Tests for engine/elements/boundary_postprocess.cpp (section 5.4) on the bundled dome: filling
// puts an E-element on every boundary-crossing lattice edge whose E-element centre (at the
// design's t along the whole lattice edge) lies inside the map, and nowhere else; the outside end
// moves with the inside end and retired particles fill nothing. Elimination removes exactly the
// elements whose centre is nearer the surface boundary (in 3D, measured here over every boundary
// segment) than their radius, and keeps the others in order.
#include "elements/boundary_postprocess.h"

#include "elements/element_placement.h"
#include "map/lifting.h"
#include "pattern/pattern.h"
#include "pipeline/pavement.h"
#include "surface_maps.h"
#include "map_polygon.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <set>
#include <utility>
#include <vector>

namespace paver {
namespace {

using test::boundary_polygon;
using test::inside;

const SurfaceMap& dome_map() { return *test::bundled_map("dome"); }

// Hexagonal, D = 6, half-size V-elements, E-elements at the middle of every edge and a second,
// smaller kind near the `from` end of cell edge 1 only (so the edge's direction matters).
Design filling_design() {
  Design design;
  design.pattern.tessellation = Tessellation::Hexagon;
  design.pattern.spacing = 6;
  design.elements.vertex.scale = 0.5;
  EdgeElementDesign middle;
  middle.t = 0.5, middle.scale = 0.4, middle.shape = ShapeKind::Gem;
  EdgeElementDesign near_from;
  near_from.t = 0.2, near_from.scale = 0.25, near_from.cell_edges = {1};
  design.elements.edge = {middle, near_from};
  return design;
}

struct DomeFilling {
  Design design;
  UnitCell cell;
  Pattern pattern;
};

const DomeFilling& dome_setup() {
  static const DomeFilling setup = [] {
    DomeFilling s;
    s.design = filling_design();
    s.cell = make_design_cell(s.design.pattern);
    s.pattern = build_pattern(dome_map(), s.cell, s.design.placement);
    return s;
  }();
  return setup;
}

template <class Vec>
double segment_distance(const Vec& p, const Vec& a, const Vec& b) {
  const Vec ab = b - a;
  const double t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
  return glm::length(p - (a + t * ab));
}

double distance_to_polygon(const std::vector<glm::dvec2>& polygon, glm::dvec2 p) {
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++)
    best = std::min(best, segment_distance(p, polygon[j], polygon[i]));
  return best;
}

// 3D distance from p to the surface's boundary polyline, over every segment.
double distance_to_boundary_3d(const SurfaceMap& map, const glm::dvec3& p) {
  const auto& loop = map.mesh.outer_loop();
  const auto& x = map.mesh.positions;
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < loop.size(); ++i)
    best = std::min(best, segment_distance(p, x[loop[i]], x[loop[(i + 1) % loop.size()]]));
  return best;
}

// A filling E-element as this test expects it: crossing edge, spec, centre in the map.
struct ExpectedFill {
  int crossing, spec;
  glm::dvec2 centre;
};

// Every (crossing edge, E-element kind) whose centre is inside the map. The lattice edge is
// rebuilt from the unit cell (not from the crossing edge's stored outside end); `points` moves each
// edge rigidly with its inside point. Centres within `margin` of the boundary are ambiguous and
// make the test fail, so that a pass means every case was decided.
std::vector<ExpectedFill> expected_filling(const SurfaceMap& map, const DomeFilling& s, const std::vector<glm::dvec2>& points,
                                           const std::vector<std::uint8_t>* retired, int* rejected) {
  const std::vector<glm::dvec2> polygon = boundary_polygon(map);
  std::vector<ExpectedFill> out;
  *rejected = 0;
  for (int c = 0; c < int(s.pattern.crossing_edges.size()); ++c) {
    const Pattern::CrossingEdge& crossing = s.pattern.crossing_edges[c];
    const int p = crossing.inside_point;
    if (retired && (*retired)[p]) continue;
    const CellEdge& edge = s.cell.edges[crossing.cell_edge];
    EXPECT_FALSE(edge.is_virtual) << "crossing edge " << c << " is virtual";
    const int v = s.pattern.point_cell_vertex[p];
    const glm::ivec2 lattice_cell = s.pattern.point_cell[p];
    glm::dvec2 from, to;
    if (crossing.inside_is_from) {
      EXPECT_EQ(v, edge.from);
      from = s.cell.position(edge.from, lattice_cell);
      to = s.cell.position(edge.to, lattice_cell + edge.offset);
    } else {
      EXPECT_EQ(v, edge.to);
      from = s.cell.position(edge.from, lattice_cell - edge.offset);
      to = s.cell.position(edge.to, lattice_cell);
    }
    from = s.design.placement.pattern_to_map(from), to = s.design.placement.pattern_to_map(to);
    const glm::dvec2 shift = points[p] - s.pattern.points[p];
    from += shift, to += shift;
    for (int k = 0; k < int(s.design.elements.edge.size()); ++k) {
      const EdgeElementDesign& spec = s.design.elements.edge[k];
      if (!spec.cell_edges.empty() &&
          std::find(spec.cell_edges.begin(), spec.cell_edges.end(), crossing.cell_edge) == spec.cell_edges.end())
        continue;
      const glm::dvec2 centre = from + spec.t * (to - from);
      EXPECT_GT(distance_to_polygon(polygon, centre), 1e-6) << "ambiguous case: crossing edge " << c;
      if (inside(polygon, centre))
        out.push_back({c, k, centre});
      else
        ++*rejected;
    }
  }
  return out;
}

// Runs fill_boundary_edges on `points` after the V- and E-elements of place_elements and checks
// the appended elements one by one against expected_filling (which must have `at_least` elements
// filled and `at_least` left out, so that both cases are exercised).
void check_filling(const std::vector<glm::dvec2>& points, const std::vector<std::uint8_t>* retired, int at_least) {
  const SurfaceMap& map = dome_map();
  const DomeFilling& s = dome_setup();
  const double spacing = s.design.pattern.spacing;
  Elements elements = place_elements(map, s.pattern, points, s.design.elements, spacing, retired);
  const Elements placed = elements;
  const int added = fill_boundary_edges(map, s.pattern, points, s.design.elements, spacing, elements, retired);

  int rejected = 0;
  const std::vector<ExpectedFill> want = expected_filling(map, s, points, retired, &rejected);
  ASSERT_GE(int(want.size()), at_least) << "the dome should have E-elements to fill";
  ASSERT_GE(rejected, at_least) << "and E-elements that fall outside";
  ASSERT_EQ(added, int(want.size()));
  ASSERT_EQ(elements.size(), placed.size() + want.size());

  // The elements placed before are untouched.
  for (size_t i = 0; i < placed.size(); ++i) ASSERT_EQ(elements.uv[i], placed.uv[i]) << i;

  std::set<std::pair<int, int>> got_keys;
  for (size_t i = placed.size(); i < elements.size(); ++i) {
    EXPECT_EQ(elements.kind[i], ElementKind::Edge);
    ASSERT_LT(elements.source[i], 0) << "a filling element names its crossing edge as -1 - index";
    got_keys.emplace(-1 - elements.source[i], elements.spec[i]);
  }
  std::set<std::pair<int, int>> want_keys;
  for (const ExpectedFill& f : want) want_keys.emplace(f.crossing, f.spec);
  ASSERT_EQ(got_keys, want_keys);

  LiftedPoints lifted;
  lifted.resize(1);
  for (size_t i = placed.size(); i < elements.size(); ++i) {
    const int c = -1 - elements.source[i], spec = elements.spec[i];
    const auto f = std::find_if(want.begin(), want.end(), [&](const ExpectedFill& e) {
      return e.crossing == c && e.spec == spec;
    });
    ASSERT_NE(f, want.end());
    const EdgeElementDesign& design = s.design.elements.edge[spec];
    EXPECT_NEAR(glm::length(elements.uv[i] - f->centre), 0, 1e-9) << "crossing edge " << c << " spec " << spec;
    EXPECT_DOUBLE_EQ(elements.diameter[i], design.scale * spacing);
    EXPECT_EQ(elements.shape[i], design.shape);
    // On the surface, lifted from its uv, with a unit normal.
    ASSERT_EQ(lift_points(map, std::vector<glm::dvec2>{elements.uv[i]}, lifted), 0);
    EXPECT_NEAR(glm::length(elements.position[i] - lifted.position[0]), 0, 1e-9);
    EXPECT_NEAR(glm::length(elements.normal[i]), 1, 1e-9);
  }
}

TEST(BoundaryFilling, AddsTheEElementsOfCrossingEdgesThatFallInsideTheMap) {
  check_filling(dome_setup().pattern.points, nullptr, 30);
}

TEST(BoundaryFilling, TheOutsideEndMovesWithTheInsideEnd) {
  // Optimised points: every particle moved by its own small displacement, staying in the map.
  const std::vector<glm::dvec2> polygon = boundary_polygon(dome_map());
  std::vector<glm::dvec2> points = dome_setup().pattern.points;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> jitter(-0.8, 0.8);
  int moved = 0;
  for (glm::dvec2& p : points) {
    const glm::dvec2 q = p + glm::dvec2(jitter(rng), jitter(rng));
    if (inside(polygon, q) && distance_to_polygon(polygon, q) > 1e-3) p = q, ++moved;
  }
  ASSERT_GT(moved, int(0.9 * double(points.size())));
  check_filling(points, nullptr, 30);
}

TEST(BoundaryFilling, RetiredParticlesFillNothing) {
  const DomeFilling& s = dome_setup();
  std::vector<std::uint8_t> retired(s.pattern.points.size(), 0);
  int crossing_retired = 0;
  for (size_t c = 0; c < s.pattern.crossing_edges.size(); c += 2) {
    retired[s.pattern.crossing_edges[c].inside_point] = 1;
    ++crossing_retired;
  }
  ASSERT_GT(crossing_retired, 10);
  check_filling(s.pattern.points, &retired, 10);
}

TEST(BoundaryFilling, NoEElementsNothingToFill) {
  const DomeFilling& s = dome_setup();
  ElementsDesign vertex_only = s.design.elements;
  vertex_only.edge.clear();
  Elements elements;
  EXPECT_EQ(fill_boundary_edges(dome_map(), s.pattern, s.pattern.points, vertex_only, 6, elements), 0);
  EXPECT_EQ(elements.size(), 0u);
}

// The dome's elements after filling, plus elements with random diameters at random places of the
// map (many near the boundary).
Elements elements_to_eliminate() {
  const SurfaceMap& map = dome_map();
  const DomeFilling& s = dome_setup();
  Elements elements = place_elements(map, s.pattern, s.pattern.points, s.design.elements, 6);
  fill_boundary_edges(map, s.pattern, s.pattern.points, s.design.elements, 6, elements);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(map.uv_min.x, map.uv_max.x), v(map.uv_min.y, map.uv_max.y),
      diameter(0.5, 12);
  std::vector<glm::dvec2> uv(3000);
  for (glm::dvec2& p : uv) p = {u(rng), v(rng)};
  LiftedPoints lifted;
  lifted.resize(uv.size());
  lift_points(map, uv, lifted);
  for (size_t i = 0; i < uv.size(); ++i)
    if (lifted.triangle[i] >= 0)
      elements.push_back(ElementKind::Vertex, int(i), 0, uv[i], lifted.position[i], lifted.normal[i], diameter(rng),
                         ShapeKind::Sphere);
  return elements;
}

TEST(BoundaryElimination, RemovesExactlyTheElementsNearerTheBoundaryThanTheirRadius) {
  const SurfaceMap& map = dome_map();
  Elements elements = elements_to_eliminate();
  const Elements before = elements;
  std::vector<std::size_t> keep;
  for (std::size_t i = 0; i < before.size(); ++i) {
    const double d = distance_to_boundary_3d(map, before.position[i]), r = 0.5 * before.diameter[i];
    ASSERT_GT(std::abs(d - r), 1e-9) << "element " << i << " is too close to the threshold to decide";
    if (d >= r) keep.push_back(i);
  }
  const int removed_expected = int(before.size() - keep.size());
  ASSERT_GT(removed_expected, 50);
  ASSERT_GT(keep.size(), 500u);

  EXPECT_EQ(eliminate_boundary_elements(map, elements), removed_expected);
  ASSERT_EQ(elements.size(), keep.size());
  for (std::size_t k = 0; k < keep.size(); ++k) {
    const std::size_t i = keep[k];
    EXPECT_EQ(elements.position[k], before.position[i]) << k;
    EXPECT_EQ(elements.uv[k], before.uv[i]) << k;
    EXPECT_EQ(elements.diameter[k], before.diameter[i]) << k;
    EXPECT_EQ(elements.kind[k], before.kind[i]) << k;
    EXPECT_EQ(elements.source[k], before.source[i]) << k;
    EXPECT_EQ(elements.spec[k], before.spec[i]) << k;
    EXPECT_EQ(elements.shape[k], before.shape[i]) << k;
  }
  // Nothing left crosses; a second pass removes nothing.
  EXPECT_EQ(eliminate_boundary_elements(map, elements), 0);
}

// A jeweller's edge margin (elements.margin): every footprint keeps that much more from the
// boundary, wider than the largest element, so the search must reach past a diameter.
TEST(BoundaryElimination, AMarginKeepsEveryFootprintThatFarFromTheBoundary) {
  const SurfaceMap& map = dome_map();
  Elements elements = elements_to_eliminate();
  const Elements before = elements;
  const double margin = 15;  // above the largest diameter (12)
  std::size_t keep = 0;
  for (std::size_t i = 0; i < before.size(); ++i) {
    const double d = distance_to_boundary_3d(map, before.position[i]), need = 0.5 * before.diameter[i] + margin;
    ASSERT_GT(std::abs(d - need), 1e-9) << "element " << i << " is too close to the threshold to decide";
    keep += d >= need;
  }
  ASSERT_GT(keep, 100u);
  EXPECT_EQ(eliminate_boundary_elements(map, elements, margin), int(before.size() - keep));
  ASSERT_EQ(elements.size(), keep);
  for (std::size_t k = 0; k < elements.size(); ++k)
    EXPECT_GE(distance_to_boundary_3d(map, elements.position[k]), 0.5 * elements.diameter[k] + margin) << k;
  EXPECT_TRUE(keeps_margin(10.5, 1, 10));
  EXPECT_FALSE(keeps_margin(10.4999, 1, 10));
}

TEST(BoundaryElimination, DistancesAreExactWithinTheLargestDiameter) {
  // distances_to_boundary only searches one largest diameter around each element: nearer than
  // that it is the exact 3D distance, farther it reports at least that diameter.
  const SurfaceMap& map = dome_map();
  const Elements elements = elements_to_eliminate();
  const double largest = *std::max_element(elements.diameter.begin(), elements.diameter.end());
  const std::vector<double> got = distances_to_boundary(map, elements);
  ASSERT_EQ(got.size(), elements.size());
  int near = 0;
  for (std::size_t i = 0; i < elements.size(); ++i) {
    const double want = distance_to_boundary_3d(map, elements.position[i]);
    if (want < largest) {
      ++near;
      EXPECT_NEAR(got[i], want, 1e-9) << "element " << i;
    } else {
      EXPECT_GE(got[i], largest) << "element " << i;
    }
  }
  EXPECT_GT(near, 100);
}

}  // namespace
}  // namespace paver
