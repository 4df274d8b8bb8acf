// set_stone_size (paver run --stone, the studio's stone diameter): a pavé of vertex stones gets
// D = stone + gap; a design with edge stones between them keeps its proportions, so the bundled
// gem pendants take a stone size instead of refusing it.
#include "design/design.h"

#include <cmath>
#include "io/design_io.h"
#include "pipeline/pavement.h"
#include "surface_maps.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace paver {
namespace {

TEST(StoneSize, APaveOfVertexStonesIsTheStonePlusTheGapApart) {
  Design design;
  design.elements.gap = 0.1;
  set_stone_size(design, 1.5);
  EXPECT_DOUBLE_EQ(design.pattern.spacing, 1.6);
  EXPECT_DOUBLE_EQ(design.elements.vertex.scale * design.pattern.spacing, 1.5);
  EXPECT_EQ(design.elements.vertex.shape, ShapeKind::Gem);
}

TEST(StoneSize, ADesignWithEdgeStonesKeepsItsProportions) {
  Design design = load_design(test::source_dir() / "assets/designs/pendant_pierced_tri_gems.json");
  const double vertex_scale = design.elements.vertex.scale, edge_scale = design.elements.edge.at(0).scale;
  set_stone_size(design, 1.2);
  EXPECT_DOUBLE_EQ(design.pattern.spacing, 1.2 / vertex_scale);
  EXPECT_EQ(design.elements.vertex.scale, vertex_scale);
  EXPECT_EQ(design.elements.edge.at(0).scale, edge_scale);
  // It paves: every vertex stone is 1.2 but those the bare spots took at the edge stones' own size
  // (elements/bare_spots.h), and no pair is in contact.
  const Pavement p = make_pavement(*test::bundled_map("pendant_pierced"), design);
  const double edge_stone = edge_scale * design.pattern.spacing;
  long vertex_stones = 0, of_edge_size = 0;
  for (std::size_t i = 0; i < p.elements.size(); ++i)
    if (p.elements.kind[i] == ElementKind::Vertex) {
      const bool main = std::abs(p.elements.diameter[i] - 1.2) <= 1e-9;
      vertex_stones += main;
      of_edge_size += !main;
      if (!main) EXPECT_NEAR(p.elements.diameter[i], edge_stone, 1e-9);
    }
  EXPECT_GT(vertex_stones, 100);
  EXPECT_EQ(of_edge_size, p.spots_closed.of_edge_size);
  EXPECT_EQ(p.after.contact_violations, 0);
}

// The studio's gap field: the stones keep their size, and their shape.
TEST(StoneSize, ANewGapKeepsAVertexPaveStonesSizeAndShape) {
  Design design;
  design.elements.vertex.shape = ShapeKind::Sphere;
  set_gap_keeping_stone_size(design, 0.2, 1.5);
  EXPECT_DOUBLE_EQ(design.elements.gap, 0.2);
  EXPECT_DOUBLE_EQ(design.pattern.spacing, 1.7);
  EXPECT_DOUBLE_EQ(design.elements.vertex.scale * design.pattern.spacing, 1.5);
  EXPECT_EQ(design.elements.vertex.shape, ShapeKind::Sphere);
}

TEST(StoneSize, ANewGapLeavesADesignWithEdgeStonesInProportion) {
  Design design = load_design(test::source_dir() / "assets/designs/pendant_pierced_tri_gems.json");
  set_stone_size(design, 1.2);
  const Design before = design;
  set_gap_keeping_stone_size(design, 0.1, 1.2);
  EXPECT_DOUBLE_EQ(design.elements.gap, 0.1);
  EXPECT_EQ(design.pattern.spacing, before.pattern.spacing);
  EXPECT_EQ(design.elements.vertex.scale, before.elements.vertex.scale);
  EXPECT_EQ(design.elements.edge.at(0).scale, before.elements.edge.at(0).scale);
}

TEST(StoneSize, ANewGapWithoutAStoneSizeTouchesOnlyTheGap) {
  Design design;
  design.pattern.spacing = 3;
  set_gap_keeping_stone_size(design, 0.5, 0);
  EXPECT_DOUBLE_EQ(design.elements.gap, 0.5);
  EXPECT_DOUBLE_EQ(design.pattern.spacing, 3);
}

}  // namespace
}  // namespace paver
