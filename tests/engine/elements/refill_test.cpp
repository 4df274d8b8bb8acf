// Tests for engine/elements/refill.cpp: the refill puts V-elements into bare regions at the
// V-elements' own density, so a complete pattern gets none, a honeycomb with edge elements
// included (it once put a stone in every hexagon), and a hole cut into it is filled again.
#include "elements/refill.h"

#include "core/contact_rule.h"
#include "pipeline/pave_once.h"
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
  // The pass's state as the refill step gets it, with a hole 3 D across cut around the element
  // nearest the middle of the map.
  PaveState state = pave_until(map, design, {}, "refill");
  Elements& elements = state.pavement.elements;
  const Elements complete = elements;
  const glm::dvec2 middle = 0.5 * (map.uv_min + map.uv_max);
  int centre = 0;
  for (int i = 0; i < int(elements.size()); ++i)
    if (glm::length(elements.uv[i] - middle) < glm::length(elements.uv[centre] - middle)) centre = i;
  const glm::dvec3 hole = elements.position[centre];
  std::vector<std::uint8_t> in_hole(elements.size(), 0);
  for (size_t i = 0; i < elements.size(); ++i) in_hole[i] = glm::length(elements.position[i] - hole) <= 3;
  elements.erase_flagged(in_hole);
  pave_step("refill", map, {}, state);
  const RefillReport& r = state.pavement.refill;
  EXPECT_GT(r.added, 0);
  const long vertex_lost = std::count(complete.kind.begin(), complete.kind.end(), ElementKind::Vertex) -
                           (std::count(elements.kind.begin(), elements.kind.end(), ElementKind::Vertex) - r.added);
  EXPECT_LE(r.added, vertex_lost + 1) << "denser than the design's V-elements";
  for (size_t i = 0; i < elements.size(); ++i)
    for (size_t j = i + 1; j < elements.size(); ++j)
      ASSERT_FALSE(elements_collide(glm::length(elements.position[i] - elements.position[j]), elements.diameter[i],
                                    elements.diameter[j], design.elements.gap))
          << i << " and " << j;
  // The hole is filled: an added element within it.
  bool inside = false;
  for (size_t i = elements.size() - std::size_t(r.added); i < elements.size(); ++i)
    inside = inside || glm::length(elements.position[i] - hole) <= 3;
  EXPECT_TRUE(inside);
}

}  // namespace
}  // namespace paver
