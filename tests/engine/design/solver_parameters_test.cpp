// Tests for engine/design/solver_parameters.{h,cpp}: the one table of solver parameters is
// self-consistent, and the design file reader and writer, validation, the flag parser and the
// docs all follow it.
#include "design/design.h"
#include "design/solver_parameters.h"
#include "io/design_io.h"
#include "core/input_error.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <string>
#include <variant>

namespace paver {
namespace {

bool is_choice(const SolverParameter& p) { return std::holds_alternative<FilterBase SolverParams::*>(p.member); }

double value_of(const SolverParams& s, const SolverParameter& p) {
  return std::visit([&](auto member) { return double(s.*member); }, p.member);
}

// A value inside the valid range that differs from the default.
std::string other_value(const SolverParameter& p) {
  if (is_choice(p)) return "initial";
  const double d = value_of(SolverParams{}, p);
  for (double candidate : {p.slider.max, p.slider.min, (p.slider.min + p.slider.max) / 2})
    if (candidate != d && p.range.contains(candidate)) {
      if (std::holds_alternative<int SolverParams::*>(p.member)) return std::to_string(int(candidate));
      std::ostringstream text;
      text.precision(17);
      text << candidate;
      return text.str();
    }
  return "";
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SolverParameters, EveryRowIsConsistent) {
  std::set<std::string_view> names;
  ASSERT_GE(solver_parameters().size(), 16u);
  for (const SolverParameter& p : solver_parameters()) {
    SCOPED_TRACE(std::string(p.name));
    EXPECT_TRUE(names.insert(p.name).second) << "duplicate name";
    EXPECT_FALSE(p.help.empty());
    // A designer reads the studio's field in words and its tooltip with a unit; the symbol stays
    // for the reader of the paper, so a label is not the symbol again.
    EXPECT_FALSE(p.unit.empty());
    EXPECT_GE(p.label.size(), 5u);
    EXPECT_NE(p.label, p.name);
    EXPECT_EQ(p.flag.find('_'), std::string_view::npos);
    EXPECT_EQ(find_solver_parameter(p.name), &p);
    if (is_choice(p)) continue;
    const double d = value_of(SolverParams{}, p);
    EXPECT_TRUE(p.range.contains(d)) << "default " << d << " outside " << p.range.describe();
    // Sliders never offer a value the validation refuses, and reach the default.
    EXPECT_LT(p.slider.min, p.slider.max);
    EXPECT_TRUE(p.range.contains(p.slider.min)) << p.slider.min << " outside " << p.range.describe();
    EXPECT_TRUE(p.range.contains(p.slider.max)) << p.slider.max << " outside " << p.range.describe();
    EXPECT_LE(p.slider.min, d);
    EXPECT_GE(p.slider.max, d);
  }
  EXPECT_EQ(find_solver_parameter("no_such"), nullptr);
}

TEST(SolverParameters, RangesDescribeThemselves) {
  EXPECT_EQ(ValueRange::open_closed(0, 1).describe(), "in (0, 1]");
  EXPECT_EQ(ValueRange::closed(0, 1000000).describe(), "in [0, 1000000]");
  EXPECT_EQ(ValueRange::at_least(0).describe(), "finite and >= 0");
  EXPECT_EQ(ValueRange::above(0).describe(), "finite and > 0");
  EXPECT_EQ(ValueRange::any().describe(), "finite");
  EXPECT_FALSE(ValueRange::any().contains(NAN));
  EXPECT_FALSE(ValueRange::any().contains(INFINITY));
  EXPECT_FALSE(ValueRange::open_closed(0, 1).contains(0));
  EXPECT_TRUE(ValueRange::open_closed(0, 1).contains(1));
}

TEST(SolverParameters, EveryParameterRoundTripsThroughDesignJson) {
  for (const SolverParameter& p : solver_parameters()) {
    SCOPED_TRACE(std::string(p.name));
    Design d;
    const std::string text = other_value(p);
    ASSERT_FALSE(text.empty());
    ASSERT_EQ(set_solver_parameter(d.solver, p, text), std::nullopt);
    const nlohmann::json json = design_to_json(d);
    ASSERT_TRUE(json["solver"].contains(std::string(p.name)));
    const Design back = design_from_json(json, "test");
    EXPECT_EQ(value_of(back.solver, p), value_of(d.solver, p));
    EXPECT_NE(value_of(back.solver, p), value_of(SolverParams{}, p));
  }
  // Exactly the table's keys are written.
  EXPECT_EQ(design_to_json(Design{})["solver"].size(), solver_parameters().size());
}

TEST(SolverParameters, ValidationRefusesEveryOutOfRangeValueByName) {
  for (const SolverParameter& p : solver_parameters()) {
    if (is_choice(p)) continue;
    SCOPED_TRACE(std::string(p.name));
    const double bad = std::isfinite(p.range.max) ? p.range.max + 1 : std::isfinite(p.range.min) ? p.range.min - 1 : NAN;
    nlohmann::json json = design_to_json(Design{});
    if (std::isnan(bad)) json["solver"][std::string(p.name)] = nullptr;  // any-finite: wrong type instead
    else json["solver"][std::string(p.name)] = bad;
    const std::string message = error_of([&] { design_from_json(json, "d.json"); });
    EXPECT_NE(message.find("'solver." + std::string(p.name) + "'"), std::string::npos) << message;
    if (!std::isnan(bad)) {
      EXPECT_NE(message.find(p.range.describe()), std::string::npos) << message;
      SolverParams s;
      const auto problem = set_solver_parameter(s, p, std::to_string(bad));
      ASSERT_TRUE(problem.has_value());
      EXPECT_EQ(*problem, "must be " + p.range.describe());
      EXPECT_EQ(value_of(s, p), value_of(SolverParams{}, p)) << "a refused value must leave the parameter alone";
    }
  }
}

TEST(SolverParameters, NaNIsShownAsNaN) {
  SolverParams s;
  s.alpha = -std::numeric_limits<double>::quiet_NaN();
  Design d;
  d.solver = s;
  const std::string message = error_of([&] { validate_design(d, "d.json"); });
  EXPECT_NE(message.find("'solver.alpha' must be in (0, 1000000], got NaN"), std::string::npos) << message;
}

TEST(SolverParameters, UnknownKeySuggestsTheTablesName) {
  nlohmann::json json = design_to_json(Design{});
  json["solver"]["lamda_r"] = 0.5;
  const std::string message = error_of([&] { design_from_json(json, "d.json"); });
  EXPECT_NE(message.find("unknown key 'solver.lamda_r' (did you mean 'solver.lambda_r'?)"), std::string::npos)
      << message;
}

TEST(SolverParameters, FlagTextIsParsedStrictly) {
  SolverParams s;
  const SolverParameter& dt = *find_solver_parameter("dt");
  EXPECT_EQ(set_solver_parameter(s, dt, "0.25"), std::nullopt);
  EXPECT_EQ(s.dt, 0.25);
  EXPECT_EQ(set_solver_parameter(s, dt, "0.25x"), "must be a number");
  EXPECT_EQ(set_solver_parameter(s, dt, ""), "must be a number");
  EXPECT_EQ(set_solver_parameter(s, dt, "nan"), "must be in (0, 1]");
  EXPECT_EQ(set_solver_parameter(s, dt, "-nan"), "must be in (0, 1]");
  const SolverParameter& iterations = *find_solver_parameter("iterations");
  EXPECT_EQ(set_solver_parameter(s, iterations, "1.5"), "must be a whole number");
  EXPECT_EQ(set_solver_parameter(s, iterations, "700"), std::nullopt);
  EXPECT_EQ(s.iterations, 700);
  const SolverParameter& base = *find_solver_parameter("filter_base");
  EXPECT_EQ(set_solver_parameter(s, base, "sideways"), "must be \"current\" or \"initial\"");
  EXPECT_EQ(set_solver_parameter(s, base, "initial"), std::nullopt);
  EXPECT_EQ(s.filter_base, FilterBase::Initial);
}

TEST(SolverParameters, DocsTableIsTheGeneratedOne) {
  std::ifstream in(std::string(PAVER_SOURCE_DIR) + "/docs/parameters.md");
  ASSERT_TRUE(in) << "docs/parameters.md is missing";
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find(solver_parameters_markdown()), std::string::npos)
      << "docs/parameters.md is out of date: regenerate its table with `build/bin/paver parameters`";
}

}  // namespace
}  // namespace paver
