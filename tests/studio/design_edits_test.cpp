#include "design_edits.h"

#include "core/input_error.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>

namespace paver::studio {
namespace {

EdgeOperator op(EdgeOperator::Kind kind, int from, int to, glm::ivec2 offset) {
  EdgeOperator o;
  o.kind = kind;
  o.from = from;
  o.to = to;
  o.offset = offset;
  return o;
}

TEST(DesignEdits, ANewTessellationDropsWhatNamedTheOldCellsEdges) {
  Design d;
  d.pattern.tessellation = Tessellation::Triangle;
  d.pattern.operators.push_back(op(EdgeOperator::Kind::Remove, 0, 0, {1, 0}));
  d.elements.edge.push_back({.t = 0.5, .scale = 0.3, .shape = ShapeKind::Sphere, .cell_edges = {0, 1}});
  const Design same = with_tessellation(d, Tessellation::Triangle);
  EXPECT_EQ(same.pattern.operators.size(), 1u);
  EXPECT_EQ(same.elements.edge[0].cell_edges.size(), 2u);
  const Design grid = with_tessellation(d, Tessellation::Grid);
  EXPECT_EQ(grid.pattern.tessellation, Tessellation::Grid);
  EXPECT_TRUE(grid.pattern.operators.empty());
  ASSERT_EQ(grid.elements.edge.size(), 1u) << "the E-element stays, on every edge";
  EXPECT_TRUE(grid.elements.edge[0].cell_edges.empty());
}

// A drawn cell starts as the cell on screen, its operators made part of it, and is a valid cell.
TEST(DesignEdits, ADrawnCellStartsAsTheCellShownWithItsOperators) {
  Design d;
  d.pattern.tessellation = Tessellation::Grid;
  d.pattern.operators.push_back(op(EdgeOperator::Kind::Add, 0, 0, {1, 1}));  // a grid with diagonals
  const Design drawn = with_tessellation(d, Tessellation::Custom);
  EXPECT_EQ(drawn.pattern.tessellation, Tessellation::Custom);
  EXPECT_TRUE(drawn.pattern.operators.empty());
  ASSERT_EQ(drawn.pattern.cell.vertices.size(), 1u);
  EXPECT_EQ(drawn.pattern.cell.edges.size(), 3u) << "the grid's two edges and the added diagonal";
  const UnitCell cell = design_cell_shape(drawn.pattern);
  EXPECT_EQ(cell_faces(cell).size(), 2u) << "two triangles, as the grid with its diagonal had";
  // Back to the grid and to the drawn cell again: the drawing is kept, not redrawn.
  Design edited = drawn;
  edited.pattern.cell.vertices[0].at = {0.25, 0.5};
  const Design again = with_tessellation(with_tessellation(edited, Tessellation::Grid), Tessellation::Custom);
  EXPECT_EQ(again.pattern.cell.vertices[0].at, glm::dvec2(0.25, 0.5));
}

// A designer's trial: the unit-cell editor re-centred after each change, so the next click missed.
// Its centre is one no edge operator moves; the edges' own centre (what it used) moves.
TEST(DesignEdits, TheCellEditorsCentreHoldsAsEdgesAreEdited) {
  for (const Tessellation t : {Tessellation::Hexagon, Tessellation::Grid, Tessellation::Cairo}) {
    Design d;
    d.pattern.tessellation = t;
    const UnitCell cell = design_cell_shape(d.pattern);
    const auto edges_centre = [](const UnitCell& c) {
      glm::dvec2 sum(0);
      int n = 0;
      for (const CellEdge& e : c.edges)
        if (!e.is_virtual) sum += 0.5 * (c.vertices[e.from] + c.position(e.to, e.offset)), ++n;
      return sum / double(n);
    };
    const CellEdge& e = cell.edges[0];
    const Design removed = with_operator(d, op(EdgeOperator::Kind::Remove, e.from, e.to, e.offset));
    const UnitCell after = design_cell_shape(removed.pattern);
    EXPECT_GT(glm::length(edges_centre(after) - edges_centre(cell)), 1e-3) << enum_name(t) << ": the old centre moved";
    EXPECT_EQ(cell_view_centre(after), cell_view_centre(cell)) << enum_name(t);
    const Design added = with_operator(d, op(EdgeOperator::Kind::Add, 0, 0, {1, 1}));
    EXPECT_EQ(cell_view_centre(design_cell_shape(added.pattern)), cell_view_centre(cell)) << enum_name(t);
  }
}

TEST(DesignEdits, OperatorsAreAddedOnlyWhenTheCellTakesThem) {
  Design d;
  d.pattern.tessellation = Tessellation::Triangle;
  const UnitCell cell = design_cell_shape(d.pattern);
  ASSERT_FALSE(cell.edges.empty());
  const CellEdge& e = cell.edges[0];
  const Design removed = with_operator(d, op(EdgeOperator::Kind::Remove, e.from, e.to, e.offset));
  ASSERT_EQ(removed.pattern.operators.size(), 1u);
  const auto real_edges = [](const UnitCell& c) {
    return std::count_if(c.edges.begin(), c.edges.end(), [](const CellEdge& x) { return !x.is_virtual; });
  };
  EXPECT_EQ(real_edges(design_cell_shape(removed.pattern)), real_edges(cell) - 1);
  // The same edge cannot go twice, and a far edge that is not there cannot go at all.
  EXPECT_THROW(with_operator(removed, op(EdgeOperator::Kind::Remove, e.from, e.to, e.offset)), InputError);
  EXPECT_THROW(with_operator(d, op(EdgeOperator::Kind::Flip, 0, 0, {5, 5})), InputError);
  EXPECT_TRUE(d.pattern.operators.empty()) << "the given design is untouched";

  const Design back = without_operator(removed, 0);
  EXPECT_TRUE(back.pattern.operators.empty());
  EXPECT_EQ(design_cell_shape(back.pattern).edges.size(), cell.edges.size());
}

TEST(DesignEdits, TheCellShapeIsDrawnAtUnitSpacing) {
  Design d;
  d.pattern.spacing = 7;
  const UnitCell cell = design_cell_shape(d.pattern);
  EXPECT_EQ(cell.spacing, 1);
}

}  // namespace
}  // namespace paver::studio
