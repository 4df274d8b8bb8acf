// Tests for design_io.cpp (design.json reading and writing) and design.cpp (validate_design).
#include "io/design_io.h"
#include "design/design_keys.h"

#include "design/design.h"
#include "core/input_error.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <sstream>
#include <string_view>
#include <string>

namespace paver {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// A design where every field differs from its default, with values that have no short decimal
// form so that the round trip has to keep every bit.
Design non_default_design() {
  Design d;
  d.units = Units::Inch;
  d.pattern.tessellation = Tessellation::Grid;
  d.pattern.spacing = 0.1 + 0.2;
  d.pattern.bracing = false;
  d.pattern.topology = Topology::Adaptive;
  d.pattern.operators.push_back({EdgeOperator::Kind::Flip, 0, 0, {1, -1}, false});
  d.pattern.operators.push_back({EdgeOperator::Kind::Add, 0, 1, {-2, 3}, true});
  d.pattern.operators.push_back({EdgeOperator::Kind::Remove, 1, 0, {0, 1}, false});
  d.elements.vertex.enabled = false;
  d.elements.vertex.scale = 1.0 / 3.0;
  d.elements.vertex.shape = ShapeKind::Gem;
  d.elements.edge.push_back({0.25, 0.4, ShapeKind::HexPrism, {0, 2}});
  d.elements.edge.push_back({1.0 / 7.0, 1, ShapeKind::Custom, {}});
  d.elements.edge.push_back({0, 0.125, ShapeKind::Disc, {1}});
  d.elements.face = {true, 0.3 / 7, ShapeKind::Disc};
  // A drawn cell is kept while another tessellation is chosen (the studio keeps it to go back to).
  d.pattern.cell.a1 = {1.0 / 3, 0.1}, d.pattern.cell.a2 = {-0.2, 2.0 / 3};
  d.pattern.cell.vertices = {{{0, 0}}, {{0.1 / 3, 0.25}}};
  d.pattern.cell.edges = {{0, 1, {0, 0}, false}, {1, 0, {1, -2}, true}};
  d.elements.custom_shape = "/shapes/star.obj";
  d.elements.allow_overlap = true;
  d.elements.gap = 0.1 / 3;
  d.elements.margin = 0.35;
  d.elements.rim_rows = RimRows::Holes;
  d.elements.close_spots = true;
  d.elements.fill_sizes = {0.1 / 3, 0.025};
  d.elements.grade = {GradeBy::None, 0.1 / 7, 0.55, {1.25, -2.5, 1.0 / 3}};  // a grade needs a tri pattern of vertex stones
  d.elements.beads = {true, 1.25, 0.4, 0.125};
  d.placement.offset = {-1.5, 2.0 / 3.0};
  d.placement.rotation_deg = -37.5;
  d.placement.scale = 1.7;
  d.placement.cut_axis = CutAxis::Y;
  d.placement.align = AlignAxis::Z;
  d.placement.fit_offset = true;
  d.solver.c = 0.05;
  d.solver.m = -0.025;
  d.solver.alpha = 11;
  d.solver.beta = 4.5;
  d.solver.gamma = 0.9;
  d.solver.lambda_r = 0.9;
  d.solver.lambda_l = 0.099;
  d.solver.lambda_g = 0.001;
  d.solver.dt = 0.03;
  d.solver.iterations = 3000;
  d.solver.threshold = 2.5e-5;
  d.solver.mu_compressed = 0.75;
  d.solver.mu_stretched = 0.25;
  d.solver.filter_max = 2;
  d.solver.filter_base = FilterBase::Initial;
  d.solver.stray_patience = 25;
  return d;
}

void expect_same(const Design& a, const Design& b) {
  EXPECT_EQ(a.units, b.units);
  EXPECT_EQ(a.pattern.tessellation, b.pattern.tessellation);
  EXPECT_EQ(a.pattern.spacing, b.pattern.spacing);
  EXPECT_EQ(a.pattern.bracing, b.pattern.bracing);
  EXPECT_EQ(a.pattern.topology, b.pattern.topology);
  ASSERT_EQ(a.pattern.operators.size(), b.pattern.operators.size());
  for (size_t i = 0; i < a.pattern.operators.size(); ++i) {
    SCOPED_TRACE("operator " + std::to_string(i));
    const EdgeOperator& x = a.pattern.operators[i];
    const EdgeOperator& y = b.pattern.operators[i];
    EXPECT_EQ(x.kind, y.kind);
    EXPECT_EQ(x.from, y.from);
    EXPECT_EQ(x.to, y.to);
    EXPECT_EQ(x.offset, y.offset);
    EXPECT_EQ(x.is_virtual, y.is_virtual);
  }
  EXPECT_EQ(a.elements.vertex.enabled, b.elements.vertex.enabled);
  EXPECT_EQ(a.elements.vertex.scale, b.elements.vertex.scale);
  EXPECT_EQ(a.elements.vertex.shape, b.elements.vertex.shape);
  ASSERT_EQ(a.elements.edge.size(), b.elements.edge.size());
  for (size_t i = 0; i < a.elements.edge.size(); ++i) {
    SCOPED_TRACE("edge element " + std::to_string(i));
    const EdgeElementDesign& x = a.elements.edge[i];
    const EdgeElementDesign& y = b.elements.edge[i];
    EXPECT_EQ(x.t, y.t);
    EXPECT_EQ(x.scale, y.scale);
    EXPECT_EQ(x.shape, y.shape);
    EXPECT_EQ(x.cell_edges, y.cell_edges);
  }
  EXPECT_EQ(a.elements.face.enabled, b.elements.face.enabled);
  EXPECT_EQ(a.elements.face.scale, b.elements.face.scale);
  EXPECT_EQ(a.elements.face.shape, b.elements.face.shape);
  EXPECT_EQ(a.pattern.cell.a1, b.pattern.cell.a1);
  EXPECT_EQ(a.pattern.cell.a2, b.pattern.cell.a2);
  ASSERT_EQ(a.pattern.cell.vertices.size(), b.pattern.cell.vertices.size());
  for (size_t i = 0; i < a.pattern.cell.vertices.size(); ++i)
    EXPECT_EQ(a.pattern.cell.vertices[i].at, b.pattern.cell.vertices[i].at) << "cell vertex " << i;
  ASSERT_EQ(a.pattern.cell.edges.size(), b.pattern.cell.edges.size());
  for (size_t i = 0; i < a.pattern.cell.edges.size(); ++i) {
    const CellEdgeDesign &x = a.pattern.cell.edges[i], &y = b.pattern.cell.edges[i];
    EXPECT_TRUE(x.from == y.from && x.to == y.to && x.offset == y.offset && x.is_virtual == y.is_virtual) << "cell edge " << i;
  }
  EXPECT_EQ(a.elements.custom_shape, b.elements.custom_shape);
  EXPECT_EQ(a.elements.allow_overlap, b.elements.allow_overlap);
  EXPECT_EQ(a.elements.gap, b.elements.gap);
  EXPECT_EQ(a.elements.margin, b.elements.margin);
  EXPECT_EQ(a.elements.rim_rows, b.elements.rim_rows);
  EXPECT_EQ(a.elements.close_spots, b.elements.close_spots);
  EXPECT_EQ(a.elements.fill_sizes, b.elements.fill_sizes);
  EXPECT_EQ(a.elements.grade.by, b.elements.grade.by);
  EXPECT_EQ(a.elements.grade.smallest, b.elements.grade.smallest);
  EXPECT_EQ(a.elements.grade.width, b.elements.grade.width);
  EXPECT_EQ(a.elements.grade.point, b.elements.grade.point);
  EXPECT_EQ(a.elements.beads.enabled, b.elements.beads.enabled);
  EXPECT_EQ(a.elements.beads.scale, b.elements.beads.scale);
  EXPECT_EQ(a.elements.beads.min_diameter, b.elements.beads.min_diameter);
  EXPECT_EQ(a.elements.beads.over, b.elements.beads.over);
  EXPECT_EQ(a.placement.offset, b.placement.offset);
  EXPECT_EQ(a.placement.rotation_deg, b.placement.rotation_deg);
  EXPECT_EQ(a.placement.scale, b.placement.scale);
  EXPECT_EQ(a.placement.cut_axis, b.placement.cut_axis);
  EXPECT_EQ(a.placement.align, b.placement.align);
  EXPECT_EQ(a.placement.fit_offset, b.placement.fit_offset);
  const SolverParams& s = a.solver;
  const SolverParams& t = b.solver;
  EXPECT_EQ(s.c, t.c);
  EXPECT_EQ(s.m, t.m);
  EXPECT_EQ(s.alpha, t.alpha);
  EXPECT_EQ(s.beta, t.beta);
  EXPECT_EQ(s.gamma, t.gamma);
  EXPECT_EQ(s.lambda_r, t.lambda_r);
  EXPECT_EQ(s.lambda_l, t.lambda_l);
  EXPECT_EQ(s.lambda_g, t.lambda_g);
  EXPECT_EQ(s.dt, t.dt);
  EXPECT_EQ(s.iterations, t.iterations);
  EXPECT_EQ(s.threshold, t.threshold);
  EXPECT_EQ(s.mu_compressed, t.mu_compressed);
  EXPECT_EQ(s.mu_stretched, t.mu_stretched);
  EXPECT_EQ(s.filter_max, t.filter_max);
  EXPECT_EQ(s.filter_base, t.filter_base);
  EXPECT_EQ(s.stray_patience, t.stray_patience);
}

// The InputError message `action` throws, or "" when it throws nothing.
std::string input_error(const std::function<void()>& action) {
  try {
    action();
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

std::string json_error(const std::string& text) {
  return input_error([&] { design_from_json(json::parse(text), "d.json"); });
}

std::string validation_error(const std::function<void(Design&)>& change) {
  Design design;
  change(design);
  return input_error([&] { validate_design(design, "d.json"); });
}

::testing::AssertionResult contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "\"" << text << "\" does not contain \"" << part << "\"";
}

TEST(DesignIo, RoundTripKeepsEveryField) {
  const Design original = non_default_design();
  expect_same(design_from_json(design_to_json(original), "mem"), original);
  // Through text as well: the numbers must survive printing and parsing.
  expect_same(design_from_json(json::parse(design_to_json(original).dump()), "mem"), original);
}

TEST(DesignIo, WritesEveryKey) {
  const json j = design_to_json(Design{});
  EXPECT_EQ(j.at("version"), Design::kVersion);
  EXPECT_EQ(Design::kVersion, 8);
  EXPECT_EQ(j.at("units"), "mm");
  EXPECT_EQ(j.at("pattern").size(), 6u);
  EXPECT_EQ(j.at("pattern").at("cell").at("a1"), json::array({1.0, 0.0}));
  EXPECT_EQ(j.at("pattern").at("cell").at("vertices"), json::array());
  EXPECT_EQ(j.at("pattern").at("topology"), "auto");
  EXPECT_EQ(j.at("elements").size(), 12u);
  EXPECT_EQ(j.at("elements").at("face").at("enabled"), false);
  EXPECT_EQ(j.at("elements").at("face").at("scale"), 0.5);
  EXPECT_EQ(j.at("elements").at("grade").size(), 4u);
  EXPECT_EQ(j.at("elements").at("grade").at("point"), json::array());
  EXPECT_EQ(j.at("elements").at("grade").at("by"), "none");
  EXPECT_EQ(j.at("elements").at("close_spots"), true);
  EXPECT_EQ(j.at("elements").at("fill_sizes"), json::array());
  EXPECT_EQ(j.at("elements").at("rim_rows"), "auto");
  EXPECT_EQ(j.at("elements").at("beads").size(), 4u);
  EXPECT_EQ(j.at("elements").at("beads").at("min_diameter"), 0.5);
  EXPECT_EQ(j.at("elements").at("vertex").size(), 3u);
  EXPECT_EQ(j.at("placement").size(), 7u);
  EXPECT_EQ(j.at("placement").at("band_rows"), "auto");
  EXPECT_EQ(j.at("placement").at("cut_axis"), "auto");
  EXPECT_EQ(j.at("placement").at("align"), "none");
  EXPECT_EQ(j.at("placement").at("fit_offset"), false);
  EXPECT_EQ(j.at("solver").size(), 17u);
  EXPECT_EQ(j.at("solver").at("coarse_levels"), 8);
  const json full = design_to_json(non_default_design());
  EXPECT_EQ(full.at("pattern").at("operators").at(1).size(), 5u);
  EXPECT_EQ(full.at("pattern").at("operators").at(1).at("op"), "add");
  EXPECT_EQ(full.at("elements").at("edge").at(0).size(), 4u);
  EXPECT_EQ(full.at("elements").at("edge").at(0).at("shape"), "hex_prism");
  EXPECT_EQ(full.at("pattern").at("tessellation"), "grid");
  EXPECT_EQ(full.at("pattern").at("topology"), "adaptive");
}

TEST(DesignIo, RimRowsAreNamed) {
  const std::string message = json_error(R"({"version": 1, "elements": {"rim_rows": "outer"}})");
  EXPECT_TRUE(contains(message, "elements.rim_rows")) << message;
  EXPECT_TRUE(contains(message, "holes")) << message;
}

TEST(DesignIo, UnitsAreNamed) {
  const std::string message = json_error(R"({"version": 1, "units": "furlong"})");
  EXPECT_TRUE(contains(message, "'units' must be one of \"mm\", \"cm\", \"m\", \"in\"")) << message;
  EXPECT_EQ(design_from_json(json::parse(R"({"version": 1, "units": "cm"})"), "d.json").units, Units::Centimetre);
  EXPECT_EQ(millimetres_per_unit(Units::Inch), 25.4);
}

TEST(DesignIo, TopologyIsLatticeAdaptiveOrAuto) {
  const std::string message = json_error(R"({"version": 1, "pattern": {"topology": "grown"}})");
  EXPECT_TRUE(contains(message, "'pattern.topology' must be one of \"lattice\", \"adaptive\", \"auto\"")) << message;
  EXPECT_EQ(design_from_json(json::parse(R"({"version": 1, "pattern": {"topology": "auto"}})"), "d.json").pattern.topology,
            Topology::Auto);
}

TEST(DesignIo, MissingKeysTakeDefaults) {
  expect_same(design_from_json(json::parse(R"({"version": 1})"), "d.json"), Design{});

  const Design d = design_from_json(json::parse(R"({
    "version": 1,
    "pattern": {"spacing": 6, "operators": [{"op": "remove", "offset": [1, 0]}]},
    "elements": {"edge": [{"t": 0.25}]},
    "solver": {"dt": 0.1}
  })"),
                                    "d.json");
  Design expected;
  expected.pattern.spacing = 6;
  expected.pattern.operators.push_back({EdgeOperator::Kind::Remove, 0, 0, {1, 0}, false});
  expected.elements.edge.push_back({0.25, EdgeElementDesign{}.scale, ShapeKind::Sphere, {}});
  expected.solver.dt = 0.1;
  expect_same(d, expected);
}

TEST(DesignIo, AcceptsIntegralNumbersWrittenAsDoubles) {
  const Design d = design_from_json(json::parse(R"({"version": 1.0, "solver": {"iterations": 700.0}})"), "d.json");
  EXPECT_EQ(d.solver.iterations, 700);
}

TEST(DesignIo, UnknownKeySuggestsTheNearestKnownKey) {
  const std::string message = json_error(R"({"version": 1, "pattern": {"spacng": 6}})");
  EXPECT_TRUE(contains(message, "d.json: unknown key 'pattern.spacng'"));
  EXPECT_TRUE(contains(message, "did you mean 'pattern.spacing'?"));

  EXPECT_TRUE(contains(json_error(R"({"version": 1, "Solver": {}})"), "did you mean 'solver'?"));
}

TEST(DesignIo, UnknownKeyWithoutNearMatchListsTheKnownKeys) {
  const std::string message = json_error(R"({"version": 1, "solver": {"x": 1}})");
  EXPECT_TRUE(contains(message, "unknown key 'solver.x'"));
  EXPECT_FALSE(contains(message, "did you mean"));
  EXPECT_TRUE(contains(message, "lambda_r"));
}

TEST(DesignIo, UnknownKeyInArrayNamesTheIndex) {
  const std::string message = json_error(R"({"version": 1, "pattern": {"operators": [
      {"op": "flip"}, {"op": "add"}, {"op": "add", "ofset": [1, 0]}]}})");
  EXPECT_TRUE(contains(message, "unknown key 'pattern.operators[2].ofset'"));
  EXPECT_TRUE(contains(message, "did you mean 'pattern.operators[2].offset'?"));
}

TEST(DesignIo, WrongTypeNamesTheKeyAndTheType) {
  EXPECT_TRUE(contains(json_error(R"({"version": 1, "solver": {"dt": "fast"}})"),
                       "d.json: 'solver.dt' must be a number, got string"));
  EXPECT_TRUE(contains(json_error(R"({"version": 1, "pattern": {"bracing": 1}})"),
                       "'pattern.bracing' must be true or false, got number"));
  EXPECT_TRUE(contains(json_error(R"({"version": 1, "pattern": []})"), "'pattern' must be an object, got array"));
  EXPECT_TRUE(contains(json_error(R"({"version": 1, "elements": {"edge": {}}})"),
                       "'elements.edge' must be an array, got object"));
  EXPECT_TRUE(contains(json_error(R"({"version": 1, "elements": {"custom_shape": null}})"),
                       "'elements.custom_shape' must be a string, got null"));
  EXPECT_TRUE(contains(json_error("[1]"), "d.json: the design must be a JSON object, got array"));
}

TEST(DesignIo, IntegersMustBeIntegers) {
  EXPECT_TRUE(contains(json_error(R"({"version": 1, "solver": {"iterations": 1.5}})"),
                       "'solver.iterations' must be an integer, got 1.5"));
  EXPECT_TRUE(contains(json_error(R"({"version": 1, "solver": {"iterations": "200"}})"),
                       "'solver.iterations' must be an integer, got string"));
  EXPECT_TRUE(contains(json_error(R"({"version": 1, "pattern": {"operators": [{}, {}, {"offset": [1, 0.5]}]}})"),
                       "'pattern.operators[2].offset[1]' must be an integer, got 0.5"));
  EXPECT_TRUE(contains(json_error(R"({"version": 1, "pattern": {"operators": [{"from": 0.5}]}})"),
                       "'pattern.operators[0].from' must be an integer"));
  EXPECT_TRUE(contains(json_error(R"({"version": 1, "elements": {"edge": [{"cell_edges": [0, true]}]}})"),
                       "'elements.edge[0].cell_edges[1]' must be an integer, got boolean"));
  EXPECT_TRUE(contains(json_error(R"({"version": 1, "solver": {"iterations": 99999999999}})"),
                       "'solver.iterations' must be an integer in"));
}

TEST(DesignIo, PairsNeedTwoEntries) {
  EXPECT_TRUE(contains(json_error(R"({"version": 1, "pattern": {"operators": [{}, {}, {"offset": [1, 0, 0]}]}})"),
                       "'pattern.operators[2].offset' must be an array of 2 integers, got an array of 3"));
  EXPECT_TRUE(contains(json_error(R"({"version": 1, "placement": {"offset": 3}})"),
                       "'placement.offset' must be an array of 2 numbers, got number"));
}

TEST(DesignIo, NamesMustBeKnown) {
  const std::string message = json_error(R"({"version": 1, "pattern": {"tessellation": "pentagon"}})");
  EXPECT_TRUE(contains(message, "'pattern.tessellation' must be one of \"tri\", \"grid\", \"hex\", \"cairo\", \"prismatic\", \"cell\", got "
                       "\"pentagon\""));
  // The command line's long names are read as well (written back short).
  EXPECT_EQ(design_from_json(json::parse(R"({"version": 2, "pattern": {"tessellation": "hexagon"}})"), "d.json")
                .pattern.tessellation,
            Tessellation::Hexagon);
  EXPECT_EQ(design_from_json(json::parse(R"({"version": 2, "pattern": {"tessellation": "square"}})"), "d.json")
                .pattern.tessellation,
            Tessellation::Grid);
  EXPECT_TRUE(contains(json_error(R"({"version": 1, "pattern": {"operators": [{"op": "split"}]}})"),
                       "'pattern.operators[0].op' must be one of \"flip\", \"add\", \"remove\""));
  EXPECT_TRUE(contains(json_error(R"({"version": 1, "elements": {"vertex": {"shape": "cube"}}})"),
                       "'elements.vertex.shape' must be one of \"sphere\", \"gem\""));
}

TEST(DesignIo, VersionIsRequiredAndOneThisBuildReads) {
  EXPECT_TRUE(contains(json_error(R"({"pattern": {}})"), "d.json: missing key 'version'"));
  const std::string newer = json_error(R"({"version": 9, "future_key": 1})");
  EXPECT_TRUE(contains(newer, "'version' is 9"));
  EXPECT_TRUE(contains(newer, "reads versions 1 to 8"));
  EXPECT_TRUE(contains(json_error(R"({"version": 0})"), "'version' is 0"));
  EXPECT_TRUE(contains(json_error(R"({"version": "1"})"), "'version' must be an integer, got string"));
}

TEST(DesignIo, OutOfRangeValuesAreRejectedWithTheirKey) {
  EXPECT_TRUE(contains(json_error(R"({"version": 1, "solver": {"dt": 0}})"), "d.json: 'solver.dt' must be in (0, 1], got 0"));
  EXPECT_TRUE(contains(json_error(R"({"version": 1, "elements": {"edge": [{}, {"t": 1.5}]}})"),
                       "'elements.edge[1].t' must be in [0, 1], got 1.5"));
  EXPECT_TRUE(contains(json_error(R"({"version": 1, "pattern": {"operators": [{"op": "flip", "virtual": true}]}})"),
                       "'pattern.operators[0].virtual' may only be true for an \"add\" operator"));
}

TEST(DesignValidate, DefaultsAreValid) {
  EXPECT_EQ(validation_error([](Design&) {}), "");
  EXPECT_EQ(input_error([] { validate_design(non_default_design(), "d.json"); }), "");
}

TEST(DesignValidate, EachRangeRuleNamesKeyRangeAndValue) {
  struct Case {
    std::function<void(Design&)> change;
    std::string expected;
  };
  const Case cases[] = {
      {[](Design& d) { d.pattern.spacing = -1; }, "'pattern.spacing' must be finite and >= 0"},
      {[](Design& d) { d.pattern.spacing = INFINITY; }, "'pattern.spacing' must be finite and >= 0"},
      {[](Design& d) { d.pattern.operators.push_back({EdgeOperator::Kind::Add, -1, 0, {1, 0}, false}); },
       "'pattern.operators[0].from' must be >= 0"},
      {[](Design& d) { d.pattern.operators.push_back({EdgeOperator::Kind::Add, 0, -2, {1, 0}, false}); },
       "'pattern.operators[0].to' must be >= 0 (a unit-cell vertex index), got -2"},
      {[](Design& d) { d.elements.vertex.scale = 0; }, "'elements.vertex.scale' must be in (0, 1]"},
      {[](Design& d) { d.elements.vertex.scale = 1.25; }, "'elements.vertex.scale' must be in (0, 1]"},
      {[](Design& d) { d.elements.edge.push_back({0.5, 0, ShapeKind::Sphere, {}}); },
       "'elements.edge[0].scale' must be in (0, 1]"},
      {[](Design& d) { d.elements.edge.push_back({1.5, 0.5, ShapeKind::Sphere, {}}); },
       "'elements.edge[0].t' must be in [0, 1], got 1.5"},
      {[](Design& d) { d.elements.edge.push_back({-0.1, 0.5, ShapeKind::Sphere, {}}); },
       "'elements.edge[0].t' must be in [0, 1], got -0.1"},
      {[](Design& d) { d.elements.edge.push_back({0.5, 0.5, ShapeKind::Sphere, {0, -1}}); },
       "'elements.edge[0].cell_edges[1]' must be >= 0"},
      {[](Design& d) { d.elements.vertex.shape = ShapeKind::Custom; },
       "'elements.vertex.shape' is \"custom\" but 'elements.custom_shape' is empty"},
      {[](Design& d) { d.elements.edge.push_back({0.5, 0.5, ShapeKind::Custom, {}}); },
       "'elements.edge[0].shape' is \"custom\" but 'elements.custom_shape' is empty"},
      {[](Design& d) { d.placement.scale = 0; }, "'placement.scale' must be finite and > 0, got 0"},
      {[](Design& d) { d.placement.scale = INFINITY; }, "'placement.scale' must be finite and > 0, got inf"},
      {[](Design& d) { d.placement.rotation_deg = NAN; }, "'placement.rotation_deg' must be finite"},
      {[](Design& d) { d.placement.offset.y = -INFINITY; }, "'placement.offset[1]' must be finite"},
      {[](Design& d) { d.solver.c = -0.1; }, "'solver.c' must be in [0, 100], got -0.1"},
      {[](Design& d) { d.solver.m = NAN; }, "'solver.m' must be in [-100, 100], got NaN"},
      {[](Design& d) {
         d.solver.c = 0.25;
         d.solver.m = -0.5;
       },
       "c + m must be >= 0 (eq. 5: the further-apart distance cannot be negative); got c = 0.25, m = -0.5"},
      {[](Design& d) { d.solver.alpha = 0; }, "'solver.alpha' must be in (0, 1000000], got 0"},
      // Past float32 (the GPU's type) the solver made non-finite positions: an internal error.
      {[](Design& d) { d.solver.c = 1e30; }, "'solver.c' must be in [0, 100], got 1e+30"},
      {[](Design& d) { d.solver.gamma = 1e39; }, "'solver.gamma' must be in [-1000000, 1000000], got 1e+39"},
      {[](Design& d) { d.pattern.operators.push_back({EdgeOperator::Kind::Add, 0, 0, {1000000, 1000000}}); },
       "'pattern.operators[0].offset[0]' must be in [-3, 3] (cells away: an edge joins nearby vertices), got 1000000"},
      {[](Design& d) { d.solver.beta = INFINITY; }, "'solver.beta' must be in [-1000000, 1000000], got inf"},
      {[](Design& d) { d.solver.gamma = NAN; }, "'solver.gamma' must be in [-1000000, 1000000], got NaN"},
      {[](Design& d) { d.solver.lambda_r = -1; }, "'solver.lambda_r' must be in [0, 1000000], got -1"},
      {[](Design& d) { d.solver.lambda_l = -0.01; }, "'solver.lambda_l' must be in [0, 1000000], got -0.01"},
      {[](Design& d) { d.solver.lambda_g = INFINITY; }, "'solver.lambda_g' must be in [0, 1000000], got inf"},
      {[](Design& d) { d.solver.dt = 0; }, "'solver.dt' must be in (0, 1], got 0"},
      {[](Design& d) { d.solver.dt = 1.5; }, "'solver.dt' must be in (0, 1], got 1.5"},
      {[](Design& d) { d.solver.iterations = -1; }, "'solver.iterations' must be in [0, 1000000], got -1"},
      {[](Design& d) { d.solver.iterations = 1000001; }, "'solver.iterations' must be in [0, 1000000]"},
      {[](Design& d) { d.solver.threshold = 0; }, "'solver.threshold' must be in (0, 1], got 0"},
      {[](Design& d) { d.solver.mu_compressed = 1.5; }, "'solver.mu_compressed' must be in [0, 1], got 1.5"},
      {[](Design& d) { d.solver.mu_stretched = -0.5; }, "'solver.mu_stretched' must be in [0, 1]"},
      {[](Design& d) { d.solver.filter_max = 0.9; }, "'solver.filter_max' must be in [1, 1000], got 0.9"},
      {[](Design& d) { d.solver.stray_patience = -1; }, "'solver.stray_patience' must be in [0, 1000000], got -1"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.expected);
    const std::string message = validation_error(c.change);
    EXPECT_EQ(message.rfind("d.json: ", 0), 0u) << message;
    EXPECT_TRUE(contains(message, c.expected));
  }
}

TEST(DesignValidate, BoundaryValuesAreAccepted) {
  EXPECT_EQ(validation_error([](Design& d) {
              d.pattern.spacing = 0;
              d.elements.vertex.scale = 1;
              d.elements.edge.push_back({0, 1, ShapeKind::Sphere, {0}});
              d.elements.edge.push_back({1, 1e-9, ShapeKind::Gem, {}});
              d.solver.c = 0;
              d.solver.m = 0;
              d.solver.dt = 1;
              d.solver.iterations = 0;
              d.solver.mu_compressed = 0;
              d.solver.mu_stretched = 1;
              d.solver.filter_max = 1;
              d.solver.lambda_g = 0;
            }),
            "");
  EXPECT_EQ(validation_error([](Design& d) {
              d.solver.c = 0.5;
              d.solver.m = -0.5;
              d.solver.iterations = 1000000;
            }),
            "");
  // A disabled vertex element does not use its shape, so it needs no custom_shape.
  EXPECT_EQ(validation_error([](Design& d) {
              d.elements.vertex.enabled = false;
              d.elements.vertex.shape = ShapeKind::Custom;
            }),
            "");
  EXPECT_EQ(validation_error([](Design& d) {
              d.elements.edge.push_back({0.5, 0.5, ShapeKind::Custom, {}});
              d.elements.custom_shape = "star.obj";
            }),
            "");
}

class DesignIoFile : public ::testing::Test {
protected:
  void SetUp() override {
    const std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    dir_ = fs::temp_directory_path() / ("paver_design_io_" + name + "_" + std::to_string(std::random_device{}()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const fs::path& relative, const std::string& text) const {
    const fs::path path = dir_ / relative;
    fs::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }

  static std::string read(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }

  fs::path dir_;
};

TEST_F(DesignIoFile, SyntaxErrorNamesLineAndColumn) {
  const fs::path path = write("design.json",
                              "{\n"
                              "  \"version\": 1,\n"
                              "  \"pattern\": {\n"
                              "    \"spacing\": 6.0,,\n"
                              "  }\n"
                              "}\n");
  const std::string message = input_error([&] { load_design(path); });
  EXPECT_TRUE(contains(message, path.string() + ":4:20: JSON syntax error: ")) << message;
  // The reason is kept short: nlohmann's own prefix and position are dropped.
  EXPECT_FALSE(contains(message, "json.exception"));
  EXPECT_FALSE(contains(message, "column"));
}

TEST_F(DesignIoFile, AKeyGivenTwiceIsRefusedByItsPath) {
  // JSON keeps the last value without a word: the designer's first one was lost.
  const fs::path path = write("design.json", R"({"version": 2, "pattern": {"spacing": 6, "tessellation": "hex", "spacing": 3}})");
  const std::string message = input_error([&] { load_design(path); });
  EXPECT_TRUE(contains(message, path.string() + ": 'pattern.spacing' is given twice")) << message;
  // The same key in two objects is no duplicate.
  EXPECT_NO_THROW(load_design(write("ok.json", R"({"version": 2, "placement": {"offset": [0, 0]},
                                                   "edits": {"moved": [], "deleted": [], "added": []}})")));
}

TEST_F(DesignIoFile, TruncatedFileNamesTheEnd) {
  const fs::path path = write("design.json", "{\n  \"version\": 1,\n");
  const std::string message = input_error([&] { load_design(path); });
  EXPECT_TRUE(contains(message, path.string() + ":3:1: JSON syntax error: ")) << message;
  EXPECT_TRUE(contains(message, "end of input"));
}

TEST_F(DesignIoFile, MissingFileIsNamed) {
  const fs::path path = dir_ / "nowhere.json";
  EXPECT_TRUE(contains(input_error([&] { load_design(path); }), path.string() + ": no such design file"));
  EXPECT_TRUE(contains(input_error([&] { load_design(dir_); }), dir_.string() + ": is a folder"));
}

TEST_F(DesignIoFile, ErrorsInsideTheFileNameTheFile) {
  const fs::path path = write("design.json", R"({"version": 1, "solver": {"dt": 0}})");
  EXPECT_TRUE(contains(input_error([&] { load_design(path); }), path.string() + ": 'solver.dt' must be in (0, 1]"));
}

TEST_F(DesignIoFile, RelativeCustomShapeIsResolvedAgainstTheDesignFolder) {
  const std::string text = R"({"version": 1, "elements": {"vertex": {"shape": "custom"},
                              "custom_shape": "shapes/../shapes/star.obj"}})";
  const fs::path path = write("project/design.json", text);
  const Design loaded = load_design(path);
  EXPECT_EQ(loaded.elements.custom_shape, (fs::absolute(dir_) / "project" / "shapes" / "star.obj").string());
  EXPECT_TRUE(fs::path(loaded.elements.custom_shape).is_absolute());

  // design_from_json has no folder to resolve against: it keeps the path as given.
  EXPECT_EQ(design_from_json(json::parse(text), "mem").elements.custom_shape, "shapes/../shapes/star.obj");

  // An absolute path is kept as it is.
  const fs::path absolute_path = write("abs.json", R"({"version": 1, "elements": {"custom_shape": "/opt/gem.obj"}})");
  EXPECT_EQ(load_design(absolute_path).elements.custom_shape, "/opt/gem.obj");
}

TEST_F(DesignIoFile, ACustomShapeNearTheSavedFileIsSavedRelativeToIt) {
  Design design;
  design.elements.vertex.shape = ShapeKind::Custom;
  const fs::path root = fs::absolute(dir_);
  const auto saved_shape = [&](const fs::path& design_path, const fs::path& shape) {
    design.elements.custom_shape = shape.string();
    fs::create_directories(design_path.parent_path());
    save_design(design_path, design);
    const std::string shape_text = json::parse(read(design_path))["elements"]["custom_shape"];
    // Whatever is written, loading gives the same shape back.
    EXPECT_EQ(fs::path(load_design(design_path).elements.custom_shape).lexically_normal(), shape.lexically_normal());
    return shape_text;
  };
  // A project saved beside its shapes, or an output folder beside them: the tree travels whole.
  EXPECT_EQ(saved_shape(root / "project" / "design.json", root / "project" / "shapes" / "star.obj"), "shapes/star.obj");
  EXPECT_EQ(saved_shape(root / "project" / "out" / "design.json", root / "project" / "shapes" / "star.obj"),
            "../shapes/star.obj");
  // Far away (here: three folders up and down again): the absolute path is kept.
  const fs::path far = root / "a" / "b" / "c" / "design.json";
  EXPECT_EQ(saved_shape(far, root / "x" / "star.obj"), (root / "x" / "star.obj").string());
}

TEST_F(DesignIoFile, SaveThenLoadGivesTheSameDesign) {
  const Design original = non_default_design();
  const fs::path path = dir_ / "saved.json";
  save_design(path, original);
  expect_same(load_design(path), original);

  // Pretty-printed, 2-space indent, version first, trailing newline.
  const std::string text = read(path);
  EXPECT_EQ(text.rfind("{\n  \"version\": 8,\n  \"units\": \"in\",\n  \"pattern\": {\n    \"tessellation\": \"grid\"", 0), 0u)
      << text;
  EXPECT_EQ(text.back(), '\n');

  save_design(path, Design{});
  expect_same(load_design(path), Design{});
}

}  // namespace
}  // namespace paver

namespace paver {
namespace {

// A version 1 file holding that version's default mu_stretched keeps it and says so; a file of
// today's version, or one without the key, says nothing.
TEST(DesignVersions, AnOldDefaultIsKeptAndNoted) {
  std::vector<std::string> notes;
  const Design old = design_from_json(nlohmann::json::parse(R"({"version": 1, "solver": {"mu_stretched": 0.5}})"),
                                      "old.json", &notes);
  EXPECT_EQ(old.solver.mu_stretched, 0.5);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("old.json: saved by an earlier Paver (design version 1)"), std::string::npos) << notes[0];
  EXPECT_NE(notes[0].find("0.75"), std::string::npos) << notes[0];

  for (const char* quiet : {R"({"version": 2, "solver": {"mu_stretched": 0.5}})", R"({"version": 1})",
                            R"({"version": 1, "solver": {"mu_stretched": 0.6}})"}) {
    notes.clear();
    design_from_json(nlohmann::json::parse(quiet), "d.json", &notes);
    EXPECT_TRUE(notes.empty()) << quiet;
  }
  EXPECT_EQ(design_from_json(nlohmann::json::parse(R"({"version": 1})"), "d.json").solver.mu_stretched,
            SolverParams{}.mu_stretched);
}

}  // namespace
}  // namespace paver

namespace paver {
namespace {

// docs/design_file.md's key table is the one `paver keys` prints from the key table, and every
// value a design file can hold (design_to_json writes them all) is a row of it.
void value_paths(const nlohmann::json& value, const std::string& path, std::vector<std::string>& out) {
  if (value.is_object()) {
    for (const auto& [key, child] : value.items()) value_paths(child, path.empty() ? key : path + "." + key, out);
  } else {
    out.push_back(path);
  }
}

TEST(DesignFileDocs, TheKeyTableIsTheOneTheKeysMake) {
  std::ifstream in(std::string(PAVER_SOURCE_DIR) + "/docs/design_file.md");
  ASSERT_TRUE(in) << "docs/design_file.md is missing";
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find(design_keys_markdown()), std::string::npos)
      << "docs/design_file.md is out of date: regenerate its key table with `build/bin/paver keys`";
  std::vector<std::string> paths;
  value_paths(design_to_json(Design{}), "", paths);
  ASSERT_GT(paths.size(), 40u);
  for (const std::string& path : paths)
    EXPECT_NE(text.str().find("| `" + path + "` |"), std::string::npos) << path << " is not in docs/design_file.md";
}

}  // namespace
}  // namespace paver
