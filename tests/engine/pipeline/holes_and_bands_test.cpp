// Bands and surfaces with holes, paved as a user would (default design, topology auto, default
// spacing): the independent all-pairs count finds no pair under the contact rule, nothing crosses
// any loop, the pattern covers at least 85% of the ideal count (issue 12's bar), and the report
// counts the loops.
#include "all_pairs.h"
#include "pattern/default_spacing.h"
#include "pipeline/pavement.h"
#include "report/verdict.h"
#include "plain_edges.h"
#include "surface_maps.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <string>
#include <tuple>

namespace paver {
namespace {

using Case = std::tuple<std::string, Tessellation>;
class HolesAndBands : public ::testing::TestWithParam<Case> {};

TEST_P(HolesAndBands, NoContactNoCrossingAndFillOfAtLeast85Percent) {
  const auto& [name, tessellation] = GetParam();
  const auto map = test::named_map(name);
  ASSERT_GE(map->mesh.boundary_loops.size(), 2u);
  Design design;
  design.pattern.tessellation = tessellation;
  design.pattern.spacing = default_spacing(map->mesh, tessellation);
  const Pavement p = make_pavement(*map, design);
  ASSERT_GT(p.elements.size(), 300u);
  const test::AllPairs truth = test::all_pairs(p.elements, design.elements.gap);
  EXPECT_EQ(truth.violations, 0) << "smallest clearance " << truth.min_clearance;
  EXPECT_EQ(p.after.contact_violations, truth.violations);
  EXPECT_EQ(p.after.boundary_crossings, 0);
  EXPECT_GE(p.after.fill, 0.85);
  // Sound, with the fill; the bare spots the closing leaves (docs/contact.md's table) are the
  // verdict's to name, and the edges' own tests judge them.
  const Verdict verdict = judge_pavement(p.after);
  EXPECT_TRUE(test::only_edge_problems(verdict.problems)) << test::all_problems(verdict.problems);
}

INSTANTIATE_TEST_SUITE_P(
    Surfaces, HolesAndBands,
    ::testing::Combine(::testing::ValuesIn(test::holed_surface_names()),
                       ::testing::Values(Tessellation::Triangle, Tessellation::Hexagon)),
    [](const auto& info) {
      return std::get<0>(info.param) + "_" + std::string(enum_name(std::get<1>(info.param)));
    });

}  // namespace
}  // namespace paver
