// The design key table (design/design_keys.h): one row per key in Key's order, visited once each
// in that order, its ranges the ones the reader and the flags apply, its flags the CLI's.
#include "design/design_keys.h"

#include "io/design_io.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <set>
#include <string>
#include <vector>

namespace paver {
namespace {

TEST(DesignKeys, OneRowPerKeyInKeysOrderWithPathsThatDiffer) {
  const auto keys = design_keys();
  ASSERT_GT(keys.size(), 60u);
  std::set<std::string_view> paths;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    EXPECT_EQ(std::size_t(keys[i].key), i) << keys[i].path << " is out of Key's order";
    EXPECT_TRUE(paths.insert(keys[i].path).second) << keys[i].path << " twice";
    EXPECT_FALSE(keys[i].help.empty()) << keys[i].path << " has no help";
    EXPECT_FALSE(keys[i].default_text.empty() && !keys[i].required) << keys[i].path << " has no default";
  }
}

TEST(DesignKeys, EveryKeyIsVisitedOnceInTheTablesOrder) {
  std::vector<Key> visited;
  Design design;
  design.pattern.operators.resize(1);
  design.pattern.cell.vertices.resize(1);
  design.pattern.cell.edges.resize(1);
  design.elements.edge.resize(1);
  design.edits.moved.resize(1);
  design.edits.deleted.resize(1);
  design.edits.added.resize(1);
  design.guidance.resize(1);
  visit_keys(design, [&](Key key, auto& field) {
    visited.push_back(key);
    using T = std::remove_cvref_t<decltype(field)>;
    if constexpr (requires { visit_item_keys(field[0], [](Key, auto&) {}); })
      if constexpr (!std::is_same_v<T, std::vector<int>>)
        visit_item_keys(field[0], [&](Key item_key, auto&) { visited.push_back(item_key); });
  });
  ASSERT_EQ(visited.size(), design_keys().size());
  for (std::size_t i = 0; i < visited.size(); ++i) EXPECT_EQ(std::size_t(visited[i]), i) << design_keys()[i].path;
}

TEST(DesignKeys, PathsTakeTheirItemsIndex) {
  EXPECT_EQ(key_path(Key::margin), "elements.margin");
  EXPECT_EQ(key_path(Key::edge_t, 2), "elements.edge[2].t");
  EXPECT_EQ(key_path(Key::edge_t), "elements.edge[].t");
  EXPECT_EQ(key_and_flag(Key::margin), "elements.margin (--margin)");
  EXPECT_EQ(key_and_flag(Key::vertex_scale), "elements.vertex.scale");
  ASSERT_NE(find_design_key("elements.edge[7].cell_edges"), nullptr);
  EXPECT_EQ(find_design_key("elements.edge[7].cell_edges")->key, Key::edge_cell_edges);
  EXPECT_EQ(find_design_key("elements.nothing"), nullptr);
}

TEST(DesignKeys, TheRangeCheckNamesTheFirstKeyOutOfRangeWithItsIndex) {
  Design design;
  EXPECT_FALSE(key_range_problem(design));
  design.elements.edge.resize(2);
  design.elements.edge[1].cell_edges = {0, -1};
  EXPECT_EQ(key_range_problem(design), "'elements.edge[1].cell_edges[1]' must be >= 0 (a unit-cell edge index), got -1");
  design.pattern.spacing = -2;  // an earlier key is said first
  EXPECT_EQ(key_range_problem(design),
            "'pattern.spacing' must be finite and >= 0 (0 = derive from the surface), got -2");
}

TEST(DesignKeys, FlagsSetTheirKeyOrSayWhatTheValueMustBe) {
  Design design;
  EXPECT_FALSE(set_key_from_text(design, Key::margin, "0.25"));
  EXPECT_EQ(design.elements.margin, 0.25);
  EXPECT_EQ(set_key_from_text(design, Key::margin, "-1"), "must be finite and >= 0 (surface units)");
  EXPECT_EQ(set_key_from_text(design, Key::margin, "nan"), "must be finite and >= 0 (surface units)");
  EXPECT_EQ(set_key_from_text(design, Key::margin, "1mm"), "must be a number");
  EXPECT_EQ(design.elements.margin, 0.25) << "a refused value leaves the design as it was";
  EXPECT_FALSE(set_key_from_text(design, Key::pattern_tessellation, "triangle"));
  EXPECT_EQ(design.pattern.tessellation, Tessellation::Triangle);
  EXPECT_EQ(set_key_from_text(design, Key::align, "up"), "use x, y, z or none");
  EXPECT_FALSE(set_key_from_text(design, Key::beads_enabled, ""));
  EXPECT_TRUE(design.elements.beads.enabled);
  EXPECT_EQ(set_key_from_text(design, Key::solver_iterations, "1.5"), "must be a whole number");
  EXPECT_FALSE(set_key_from_text(design, Key::solver_filter_base, "initial"));
  EXPECT_EQ(design.solver.filter_base, FilterBase::Initial);
  EXPECT_TRUE(set_key_from_text(design, Key::pattern_operators, "[]")) << "an array is no flag";
}

TEST(DesignKeys, EveryFlagIsTheKeysOwnAndTheSolversAreTheParameterTables) {
  std::set<std::string_view> flags;
  for (const Key key : flag_keys()) EXPECT_TRUE(flags.insert(design_key(key).flag).second) << design_key(key).flag;
  for (const SolverParameter& p : solver_parameters()) EXPECT_TRUE(flags.count(p.flag)) << p.flag;
  for (const std::string_view flag : {"spacing", "gap", "margin", "pattern", "topology", "units", "rim-rows", "beads",
                                      "cut", "align", "fit-offset"})
    EXPECT_TRUE(flags.count(flag)) << flag;
}

TEST(DesignKeys, DefaultsAreWhatAFreshDesignWrites) {
  const nlohmann::json written = design_to_json(Design{});
  for (const DesignKey& key : design_keys()) {
    if (key.path.find("[]") != std::string_view::npos) continue;  // an item's: no item in a fresh design
    std::string slashed = "/" + std::string(key.path);
    for (char& c : slashed) c = c == '.' ? '/' : c;
    ASSERT_TRUE(written.contains(nlohmann::json::json_pointer(slashed))) << key.path;
    const nlohmann::json& value = written.at(nlohmann::json::json_pointer(slashed));
    if (value.is_string() || value.is_boolean()) {
      EXPECT_EQ(key.default_text, value.dump()) << key.path;
    }
  }
}

}  // namespace
}  // namespace paver
