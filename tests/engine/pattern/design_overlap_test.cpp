// Tests for engine/pattern/design_overlap.cpp: a design whose elements intersect in the regular
// lattice (closer than 0.99 (r_i + r_j)) is refused with a message naming the two elements, their
// distance, what they need and the fix; a design just below that limit is accepted, whatever the
// spacing. Covers V/E, E/E on one edge, E-elements restricted to some cell edges, bracing (virtual
// edges carry no elements) and elements on long added edges.
#include "pattern/design_overlap.h"
#include "pattern/unit_cell.h"

#include "pipeline/pavement.h"

#include "input_error_assertions.h"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

namespace paver {
namespace {

using test::Contains;
using test::error_of;

EdgeElementDesign edge_element(double t, double scale, std::vector<int> cell_edges = {}) {
  EdgeElementDesign e;
  e.t = t, e.scale = scale, e.cell_edges = std::move(cell_edges);
  return e;
}

ElementsDesign elements_with(double vertex_scale, std::vector<EdgeElementDesign> edge) {
  ElementsDesign design;
  design.vertex.enabled = vertex_scale > 0;
  design.vertex.scale = vertex_scale > 0 ? vertex_scale : 1;
  design.edge = std::move(edge);
  return design;
}

// The unit cell as make_pavement builds it (with bracing unless there are operators).
UnitCell cell_of(Tessellation tessellation, double spacing, std::vector<EdgeOperator> operators = {}) {
  PatternDesign pattern;
  pattern.tessellation = tessellation;
  pattern.spacing = spacing;
  pattern.bracing = operators.empty();
  pattern.operators = std::move(operators);
  return make_design_cell(pattern);
}

bool accepted(Tessellation tessellation, const ElementsDesign& elements, double spacing = 6, double gap = 0) {
  try {
    check_design_overlaps(cell_of(tessellation, spacing), elements, spacing, gap);
    return true;
  } catch (const InputError&) {
    return false;
  }
}

TEST(DesignOverlap, VertexAndMidEdgeElementsOverlappingAreRefusedByName) {
  // Honeycomb, D = 6: a V-element and the E-element at the middle of its edge are D/2 apart.
  // Scales 0.5 and 0.52 need (0.5 + 0.52) / 2 = 0.51 D > 0.5 D.
  const double spacing = 6;
  const std::string message = error_of([&] {
    check_design_overlaps(cell_of(Tessellation::Hexagon, spacing), elements_with(0.5, {edge_element(0.5, 0.52)}),
                          spacing);
  });
  EXPECT_TRUE(Contains(message, "the design's elements overlap"));
  EXPECT_TRUE(Contains(message, "the V-element on cell vertex 0 and elements.edge[0] on cell edge 0"));
  EXPECT_TRUE(Contains(message, "are 0.5 D apart but need 0.51 D"));
  EXPECT_TRUE(Contains(message, "reduce their scales, move t"));
  EXPECT_TRUE(Contains(message, "elements.allow_overlap"));
}

TEST(DesignOverlap, JustBelowTheLimitIsAcceptedJustAboveIsRefused) {
  // The limit is exact: scale_v + scale_e = 1 with the E-element at mid-edge; no 1% forgiven.
  for (double spacing : {1.0, 6.0, 18.0}) {
    EXPECT_TRUE(accepted(Tessellation::Hexagon, elements_with(0.5, {edge_element(0.5, 0.4999)}), spacing)) << spacing;
    EXPECT_FALSE(accepted(Tessellation::Hexagon, elements_with(0.5, {edge_element(0.5, 0.5001)}), spacing)) << spacing;
    // Touching exactly (scales summing to 1) is what a uniform design does: accepted.
    EXPECT_TRUE(accepted(Tessellation::Hexagon, elements_with(0.5, {edge_element(0.5, 0.5)}), spacing)) << spacing;
  }
  // V-elements alone, scale 1: neighbours touch, which is allowed, in every tessellation.
  for (Tessellation t : {Tessellation::Triangle, Tessellation::Grid, Tessellation::Hexagon})
    EXPECT_TRUE(accepted(t, elements_with(1, {}))) << enum_name(t);
}

TEST(DesignOverlap, MidEdgeElementsOfATriangleMeetAtHalfTheSpacing) {
  // The three mid-edge points of a triangle are D/2 apart: the limit is scale 0.5, exactly.
  EXPECT_TRUE(accepted(Tessellation::Triangle, elements_with(0, {edge_element(0.5, 0.5)})));
  const std::string message = error_of([] {
    check_design_overlaps(cell_of(Tessellation::Triangle, 4), elements_with(0, {edge_element(0.5, 0.52)}), 4);
  });
  EXPECT_TRUE(Contains(message, "elements.edge[0] on cell edge "));
  EXPECT_TRUE(Contains(message, " and elements.edge[0] on cell edge "));
  EXPECT_TRUE(Contains(message, "are 0.5 D apart but need 0.52 D"));
}

TEST(DesignOverlap, TheGapIsPartOfTheRule) {
  // Triangle lattice, D = 10, V-elements of scale 0.9 (diameter 9): the free space is 1.
  EXPECT_TRUE(accepted(Tessellation::Triangle, elements_with(0.9, {}), 10, 1.0));
  EXPECT_FALSE(accepted(Tessellation::Triangle, elements_with(0.9, {}), 10, 1.01));
  const std::string message = error_of([] {
    check_design_overlaps(cell_of(Tessellation::Triangle, 10), elements_with(1, {}), 10, 0.5);
  });
  EXPECT_TRUE(Contains(message, "closer than the gap"));
  EXPECT_TRUE(Contains(message, "are 1 D apart but need 1.05 D (their radii plus the gap, 0.5 surface units)"));
  EXPECT_TRUE(Contains(message, "reduce the gap or raise the spacing"));
  // The neighbour is the same cell vertex one cell over, and the scale that fits is given.
  EXPECT_TRUE(Contains(message, "the V-element on cell vertex 0 and the V-element on cell vertex 0 of the cell at ("))
      << message;
  EXPECT_TRUE(Contains(message, "their scale can be at most 0.95 (now 1)")) << message;
  EXPECT_TRUE(Contains(message, "they touch with no gap at these scales, so none fits")) << message;
  // With room between them, the largest gap that fits is named: 1 for discs of 9 at D = 10.
  const std::string roomy = error_of([] {
    check_design_overlaps(cell_of(Tessellation::Triangle, 10), elements_with(0.9, {}), 10, 1.5);
  });
  EXPECT_TRUE(Contains(roomy, "the largest gap that fits is 1 surface units")) << roomy;
}

TEST(DesignOverlap, AGapOfManySpacingsNamesTheNearestNeighbours) {
  // A gap of 50 D reaches every element of the layout: the pair named, and the scale that fits,
  // must be the neighbours 1 D apart, not the first pair found.
  const std::string message = error_of([] {
    check_design_overlaps(cell_of(Tessellation::Triangle, 1), elements_with(1, {}), 1, 50);
  });
  EXPECT_TRUE(Contains(message, "are 1 D apart but need 51 D")) << message;
}

TEST(DesignOverlap, TwoEElementsOnOneEdgeAreNamedWithTheirIndices) {
  const std::string message = error_of([] {
    check_design_overlaps(cell_of(Tessellation::Hexagon, 6),
                          elements_with(0, {edge_element(0.3, 0.3), edge_element(0.5, 0.3)}), 6);
  });
  EXPECT_TRUE(Contains(message, "elements.edge[0] on cell edge 0 and elements.edge[1] on cell edge 0"));
  EXPECT_TRUE(Contains(message, "are 0.2 D apart but need 0.3 D"));
  // Far enough apart along the edge (0.4 D for 0.3 D), they fit.
  EXPECT_TRUE(accepted(Tessellation::Hexagon, elements_with(0, {edge_element(0.3, 0.3), edge_element(0.7, 0.3)})));
}

TEST(DesignOverlap, RestrictingEElementsToOneCellEdgeRemovesTheirOverlap) {
  // On every honeycomb edge, mid-edge elements are sqrt(3)/2 D = 0.866 D apart: scale 0.9 overlaps.
  EXPECT_FALSE(accepted(Tessellation::Hexagon, elements_with(0, {edge_element(0.5, 0.9)})));
  // On edge 0 only, the nearest other one is a lattice vector (sqrt(3) D) away.
  EXPECT_TRUE(accepted(Tessellation::Hexagon, elements_with(0, {edge_element(0.5, 0.9, {0})})));
}

TEST(DesignOverlap, VirtualEdgesCarryNoElements) {
  // With bracing the honeycomb gets its long diagonals as virtual edges; an E-element on all edges
  // at t = 0.5 would sit at the hexagon's centre on all three of them if they counted.
  const UnitCell braced = cell_of(Tessellation::Hexagon, 6);
  ASSERT_GT(braced.edges.size(), 3u);
  EXPECT_NO_THROW(check_design_overlaps(braced, elements_with(0.5, {edge_element(0.5, 0.5)}), 6));
}

// A bug found by this test: only cells -2..2 were laid out, so an E-element near the far end of an
// added edge reaching 3 cells away was never compared with the V-element it sits on.
TEST(DesignOverlap, ElementsOnALongAddedEdgeAreChecked) {
  // Grid D = 6 with an added edge 0 -> 0 @ (3, 1). An E-element at t = 0.9 on it sits at
  // (2.7, 0.9) D, 0.316 D from the V-element of cell (3, 1); scales 1 and 0.2 need 0.6 D.
  EdgeOperator add;
  add.kind = EdgeOperator::Kind::Add, add.from = 0, add.to = 0, add.offset = {3, 1};
  const UnitCell cell = cell_of(Tessellation::Grid, 6, {add});
  ASSERT_EQ(cell.edges.size(), 3u) << "grid edges 0, 1 and the added edge 2";
  const std::string message = error_of([&] {
    check_design_overlaps(cell, elements_with(1, {edge_element(0.9, 0.2, {2})}), 6);
  });
  EXPECT_TRUE(Contains(message, "the V-element on cell vertex 0 and elements.edge[0] on cell edge 2"));
}

// Pave (issue 40): the stones of the regular pattern touch, within 5% of d, with the gap. Touching
// spheres and gems with the gap do; spheres at 0.8 D do not; the pendants' gems with melee on the
// edges between them do (0.025 D apart); a honeycomb's touching stones do too (the edges' rule
// then leaves it out of pave for its wide holes, report/edge_quality.cpp).
TEST(DesignOverlap, StonesTouchInPaveNotInAPatternSpacedWider) {
  const UnitCell tri = make_unit_cell(Tessellation::Triangle, 1.6);
  ElementsDesign elements;
  EXPECT_TRUE(stones_touch(tri, elements, 0));
  elements.vertex.scale = 1.5 / 1.6;
  elements.gap = 0.1;
  EXPECT_TRUE(stones_touch(tri, elements, elements.gap)) << "1.5 mm gems 0.1 apart";
  elements.gap = 0;
  EXPECT_FALSE(stones_touch(tri, elements, 0)) << "0.1 mm apart without a gap asked: 6.7% of d";
  elements.vertex.scale = 0.8;
  EXPECT_FALSE(stones_touch(tri, elements, 0));
  elements.vertex.scale = 0.6;
  elements.edge.push_back({});
  elements.edge.back().scale = 0.35;
  EXPECT_TRUE(stones_touch(tri, elements, 0)) << "V 0.6 D and E 0.35 D gems at the middles";
  elements.allow_overlap = true;
  EXPECT_FALSE(stones_touch(tri, elements, 0)) << "overlapping by design is not pave";
  EXPECT_TRUE(stones_touch(make_unit_cell(Tessellation::Hexagon, 1), ElementsDesign{}, 0));
  ElementsDesign no_vertex;
  no_vertex.vertex.enabled = false;
  EXPECT_FALSE(stones_touch(tri, no_vertex, 0));
}

}  // namespace
}  // namespace paver
