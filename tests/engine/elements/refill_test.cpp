// Tests for engine/elements/refill.cpp: the refill puts V-elements into bare regions at the
// V-elements' own density, so a complete pattern gets none, a honeycomb with edge elements
// included (it once put a stone in every hexagon), and a hole cut into it is filled again.
#include "elements/refill.h"

#include "core/contact_rule.h"
#include "pipeline/pavement.h"
#include "report/pavement_quality.h"
#include "surface_maps.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>

namespace paver {
namespace {

Design honeycomb_with_edge_elements() {
  Design design;
  design.pattern.tessellation = Tessellation::Hexagon;
  design.pattern.spacing = 2;
  design.elements.vertex.scale = 0.5;
  design.elements.vertex.shape = ShapeKind::Gem;
  design.elements.edge.push_back(EdgeElementDesign{});
  design.elements.edge[0].t = 0.5;
  design.elements.edge[0].scale = 0.3;
  design.elements.gap = 0.05;
  design.elements.margin = 0.3;
  return design;
}

TEST(Refill, AHoneycombWithEdgeElementsKeepsItsHexagonsOpen) {
  const SurfaceMap& map = *test::bundled_map("pendant");
  const Pavement p = make_pavement(map, honeycomb_with_edge_elements(), {});
  EXPECT_EQ(p.refill.added, 0);
  EXPECT_LE(p.after.vertex_fill, 1.05);
  EXPECT_GE(p.after.regular_valence_share, 0.95);
  EXPECT_EQ(p.after.contact_violations, 0);
}

TEST(Refill, AHoleInTheHoneycombIsFilledAtTheVElementsDensity) {
  const SurfaceMap& map = *test::bundled_map("pendant");
  const Design design = honeycomb_with_edge_elements();
  PavementOptions no_refill;
  no_refill.refill = false;
  const Pavement p = make_pavement(map, design, no_refill);
  // A hole 3 D across around the element nearest the middle of the map.
  const glm::dvec2 middle = 0.5 * (map.uv_min + map.uv_max);
  int centre = 0;
  for (int i = 0; i < int(p.elements.size()); ++i)
    if (glm::length(p.elements.uv[i] - middle) < glm::length(p.elements.uv[centre] - middle)) centre = i;
  const glm::dvec3 hole = p.elements.position[centre];
  Elements kept = p.elements;
  std::vector<std::uint8_t> in_hole(kept.size(), 0);
  for (size_t i = 0; i < kept.size(); ++i) in_hole[i] = glm::length(kept.position[i] - hole) <= 3;
  kept.erase_flagged(in_hole);
  const long vertex_before = std::count(kept.kind.begin(), kept.kind.end(), ElementKind::Vertex);
  const QualityBasis basis = quality_basis(map, p.cell, design.elements, design.solver, design.guidance);
  const RefillReport r = refill_bare_regions(map, kept, p.design, basis.area_per_element / basis.vertex_share);
  EXPECT_GT(r.added, 0);
  const long vertex_lost = std::count(p.elements.kind.begin(), p.elements.kind.end(), ElementKind::Vertex) -
                           vertex_before;
  EXPECT_LE(r.added, vertex_lost + 1) << "denser than the design's V-elements";
  for (size_t i = 0; i < kept.size(); ++i)
    for (size_t j = i + 1; j < kept.size(); ++j)
      ASSERT_FALSE(elements_collide(glm::length(kept.position[i] - kept.position[j]), kept.diameter[i],
                                    kept.diameter[j], design.elements.gap))
          << i << " and " << j;
}

}  // namespace
}  // namespace paver
