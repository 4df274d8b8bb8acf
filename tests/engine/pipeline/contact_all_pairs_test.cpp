// The contact rule checked the way a sceptical user would: every bundled surface and every real
// scan in assets/scanned, paved with tri, grid and hex at their default spacing, at gap 0 and at a
// gap of 8% of D (with V-elements of scale 0.92 so that the design leaves room for it); then a
// plain loop over ALL pairs of elements, written here with no spatial structure, counts the pairs
// closer than r_i + r_j + gap and finds the smallest clearance. The pipeline must leave no such
// pair, and its report (quality_after) must give the same figures as this loop.
#include "all_pairs.h"
#include "pipeline/pavement.h"
#include "pattern/default_spacing.h"
#include "surface_maps.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <limits>
#include <string>
#include <tuple>

namespace paver {
namespace {

using test::all_pairs;
using test::AllPairs;

using Case = std::tuple<std::string, Tessellation, bool>;  // surface, tessellation, with gap
using AdaptiveCase = std::tuple<Tessellation, bool>;       // on the bunny head

// The independent count agrees with the run: none under the rule, and the report says the same.
void expect_no_contact(const Pavement& p, const Design& design) {
  ASSERT_GT(p.elements.size(), 50u);
  const AllPairs truth = all_pairs(p.elements, design.elements.gap);
  EXPECT_EQ(truth.violations, 0) << "smallest clearance " << truth.min_clearance << ", gap " << design.elements.gap;
  EXPECT_GE(truth.min_clearance, design.elements.gap);
  EXPECT_EQ(p.after.contact_violations, truth.violations);
  EXPECT_DOUBLE_EQ(p.after.min_clearance, truth.min_clearance);
  EXPECT_EQ(p.after.gap, design.elements.gap);
  EXPECT_EQ(p.after.boundary_crossings, 0);
}

class ContactAllPairs : public ::testing::TestWithParam<Case> {};

TEST_P(ContactAllPairs, NoPairCloserThanItsRadiiPlusTheGapAndTheReportAgrees) {
  const auto& [name, tessellation, with_gap] = GetParam();
  const auto map = test::named_map(name);
  Design design;
  design.pattern.tessellation = tessellation;
  design.pattern.topology = Topology::Lattice;  // the paper's pattern; adaptive and auto have their own cases
  design.pattern.spacing = default_spacing(map->mesh, tessellation);
  if (with_gap) {
    design.elements.vertex.scale = 0.92;
    design.elements.gap = 0.08 * design.pattern.spacing;
  }
  expect_no_contact(make_pavement(*map, design), design);
}

class ContactAllPairsAdaptive : public ::testing::TestWithParam<AdaptiveCase> {};

TEST_P(ContactAllPairsAdaptive, TheAdaptivePatternKeepsTheRuleToo) {
  const auto& [tessellation, with_gap] = GetParam();
  const auto map = test::named_map("bunnyhead");
  Design design;
  design.pattern.tessellation = tessellation;
  design.pattern.topology = Topology::Adaptive;
  design.pattern.spacing = default_spacing(map->mesh, tessellation);
  if (with_gap) {
    design.elements.vertex.scale = 0.92;
    design.elements.gap = 0.08 * design.pattern.spacing;
  }
  expect_no_contact(make_pavement(*map, design), design);
}

INSTANTIATE_TEST_SUITE_P(BunnyHead, ContactAllPairsAdaptive,
                         ::testing::Combine(::testing::Values(Tessellation::Triangle, Tessellation::Hexagon),
                                            ::testing::Bool()),
                         [](const auto& info) {
                           return std::string(enum_name(std::get<0>(info.param))) +
                                  (std::get<1>(info.param) ? "_gap8pct" : "_gap0");
                         });

// Float32 solver positions are taken relative to the part's centre: a part 1e5 units from the
// origin (where float32 steps are 0.008 units, 4% of this D) is paved as well as at it.
TEST(ContactFarFromTheOrigin, APartFarAwayIsPavedAsWellAsAtTheOrigin) {
  SurfaceMesh small = load_surface(test::bundled_surface("saddle")).mesh;
  for (glm::dvec3& p : small.positions) p *= 0.01;  // a 2-unit part, D about 0.2
  SurfaceMesh far = small;
  for (glm::dvec3& p : far.positions) p += glm::dvec3(1e5, -1e5, 1e5);
  Design design;
  design.pattern.tessellation = Tessellation::Triangle;
  design.pattern.spacing = default_spacing(small, Tessellation::Triangle);
  const Pavement near = make_pavement(build_surface_map(small), design);
  const Pavement away = make_pavement(build_surface_map(far), design);
  EXPECT_EQ(all_pairs(away.elements, 0).violations, 0);
  // The map itself is computed in double from shifted coordinates, so it differs in the last digits.
  EXPECT_NEAR(double(away.after.elements), double(near.after.elements), 0.03 * double(near.after.elements));
  EXPECT_GE(away.after.neighbor_ratio.p5, 0.999);
  EXPECT_NEAR(away.after.neighbor_ratio.median, near.after.neighbor_ratio.median, 1e-3);
}

std::vector<std::string> every_surface() {
  std::vector<std::string> names = test::bundled_surface_names();
  for (const std::string& scan : test::scanned_mesh_names()) names.push_back(scan);
  return names;
}

INSTANTIATE_TEST_SUITE_P(
    Surfaces, ContactAllPairs,
    ::testing::Combine(::testing::ValuesIn(every_surface()),
                       ::testing::Values(Tessellation::Triangle, Tessellation::Grid, Tessellation::Hexagon),
                       ::testing::Bool()),
    [](const auto& info) {
      return std::get<0>(info.param) + "_" + std::string(enum_name(std::get<1>(info.param))) +
             (std::get<2>(info.param) ? "_gap8pct" : "_gap0");
    });

}  // namespace
}  // namespace paver
