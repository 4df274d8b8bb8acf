// The guidance field: a painted dab makes the pattern looser or denser where it lies and leaves it
// alone elsewhere; the fill is measured against the painted density; files keep the dabs.
#include "plain_edges.h"
#include "surface_maps.h"

#include "core/input_error.h"
#include "design/guidance.h"
#include "io/design_io.h"
#include "pipeline/pavement.h"
#include "solver/guidance_field.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <limits>

namespace paver {
namespace {

TEST(GuidanceField, FactorFadesToOneAtTheRadiusAndIsClamped) {
  const std::vector<GuidanceDab> dabs = {{{0, 0}, 2, 0.4}};
  EXPECT_DOUBLE_EQ(guidance_factor(dabs, {0, 0}), 1.4);
  EXPECT_DOUBLE_EQ(guidance_factor(dabs, {2, 0}), 1.0);
  EXPECT_DOUBLE_EQ(guidance_factor(dabs, {5, 5}), 1.0);
  EXPECT_GT(guidance_factor(dabs, {1, 0}), 1.0);
  EXPECT_LT(guidance_factor(dabs, {1, 0}), 1.4);
  const std::vector<GuidanceDab> piled = {{{0, 0}, 2, 1}, {{0, 0}, 2, 1}, {{0, 0}, 2, 1}};
  EXPECT_DOUBLE_EQ(guidance_factor(piled, {0, 0}), kGuidanceMax);
}

// Mean nearest-neighbour distance (on the surface) of the vertex elements within `radius` of `uv`.
double mean_spacing_near(const Elements& e, glm::dvec2 uv, double radius) {
  double sum = 0;
  int n = 0;
  for (std::size_t i = 0; i < e.size(); ++i) {
    if (e.kind[i] != ElementKind::Vertex || glm::length(e.uv[i] - uv) > radius) continue;
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < e.size(); ++j)
      if (j != i && e.kind[j] == ElementKind::Vertex) nearest = std::min(nearest, glm::length(e.position[i] - e.position[j]));
    sum += nearest, ++n;
  }
  return sum / n;
}

TEST(GuidanceField, APaintedDabSpacesThePatternThereAndNowhereElse) {
  const auto map = test::bundled_map("pendant");
  // The pattern's own spacing, as the lattice lays it: the spots' closing (not for a painted
  // design, whose room is its design) would pack the plain one differently.
  Design design = load_design(test::source_dir() / "assets/designs/pendant_tri_gems.json");
  test::with_plain_edges(design);
  const Pavement plain = make_pavement(*map, design);
  const double D = plain.design.pattern.spacing;
  design.guidance.push_back({{0, 0}, 5 * D, 0.4});
  const Pavement looser = make_pavement(*map, design);
  const double inside = mean_spacing_near(looser.elements, {0, 0}, 1.5 * D) / mean_spacing_near(plain.elements, {0, 0}, 1.5 * D);
  EXPECT_GT(inside, 1.25) << "the painted centre is not looser";
  EXPECT_LT(inside, 1.45);
  EXPECT_EQ(looser.after.contact_violations, 0);
  // The fill is against the painted density: a looser pattern is not "bare".
  EXPECT_GT(looser.after.fill, 0.85);
  EXPECT_LT(looser.elements.size(), plain.elements.size());
  // A dab far outside the surface changes nothing.
  Design far = load_design(test::source_dir() / "assets/designs/pendant_tri_gems.json");
  far.guidance.push_back({{1000, 1000}, D, 0.5});
  far.pattern.topology = Topology::Lattice;
  test::with_plain_edges(far);
  Design same = load_design(test::source_dir() / "assets/designs/pendant_tri_gems.json");
  same.pattern.topology = Topology::Lattice;
  test::with_plain_edges(same);
  EXPECT_EQ(make_pavement(*map, far).elements.uv, make_pavement(*map, same).elements.uv);
}

TEST(GuidanceField, DabsRoundTripAndBadOnesAreRefused) {
  Design design;
  design.guidance.push_back({{1.5, -2}, 3, -0.25});
  const Design read = design_from_json(design_to_json(design), "d.json");
  ASSERT_EQ(read.guidance.size(), 1u);
  EXPECT_EQ(read.guidance[0].uv, glm::dvec2(1.5, -2));
  EXPECT_EQ(read.guidance[0].radius, 3);
  EXPECT_EQ(read.guidance[0].strength, -0.25);
  design.guidance[0].strength = -0.8;
  EXPECT_THROW(validate_design(design, "d"), InputError);
  design.guidance[0].strength = 0.2;
  design.guidance[0].radius = 0;
  EXPECT_THROW(validate_design(design, "d"), InputError);
  design.guidance[0].radius = 1;
  design.pattern.topology = Topology::Adaptive;
  EXPECT_THROW(make_pavement(*test::bundled_map("pendant"), design), InputError);
}

// The bucketed field reads only the dabs near a point, yet equals the plain sum bit for bit: a stroke
// of small dabs, a few huge ones (read by every point) and points on and off the strokes.
TEST(GuidanceField, TheBucketedFieldEqualsThePlainSumExactly) {
  std::vector<GuidanceDab> dabs;
  std::uint32_t seed = 12345;
  const auto next = [&] { return (seed = seed * 1664525u + 1013904223u) / 4294967296.0; };
  for (int i = 0; i < 3000; ++i) dabs.push_back({{40 * next(), 40 * next()}, 0.5 + next(), next() - 0.5});
  dabs.push_back({{20, 20}, 500, 0.1});
  dabs.push_back({{-100, 7}, 30, -0.2});
  const GuidanceField field(dabs);
  for (int i = 0; i < 20000; ++i) {
    const glm::dvec2 uv(-60 + 120 * next(), -60 + 120 * next());
    ASSERT_EQ(field.factor(uv), guidance_factor(dabs, uv)) << uv.x << ", " << uv.y;
  }
  for (const GuidanceDab& d : dabs) ASSERT_EQ(field.factor(d.uv), guidance_factor(dabs, d.uv));
  EXPECT_EQ(GuidanceField({}).factor({1, 2}), 1.0);
}

}  // namespace
}  // namespace paver
