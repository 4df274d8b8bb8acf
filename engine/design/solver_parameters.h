#pragma once
// The section 5 solver parameters, each described once. PAVER_SOLVER_PARAMETERS below is the
// table: one row per parameter with its type, name (design.json key "solver.<name>", CLI flag
// --<name with '-' for '_'>), default, valid range, slider range, unit and help. From it come the
// SolverParams struct, the design.json reader and writer, validation, the CLI flags, the studio's
// panel, the script's `set solver.<name>` and the docs table (docs/parameters.md, checked by a test).
// Adding a parameter is adding a row (and using it in the solver).
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>

namespace paver {

// Which l_ab the adaptive filter's clamp [l_ab, filter_max * l_ab] uses (NOTES.md: ambiguous).
enum class FilterBase {
  Current,  // recomputed every iteration from the current distortion
  Initial,  // fixed at initialisation
};

std::string_view filter_base_name(FilterBase b);  // "current", "initial"
std::optional<FilterBase> filter_base_from_name(std::string_view name);

// A closed, open or half-open interval; infinite ends are unbounded (values must still be finite).
struct ValueRange {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_open = false, max_open = false;

  static constexpr ValueRange any() { return {}; }
  static constexpr ValueRange at_least(double lo) { return {lo}; }
  static constexpr ValueRange above(double lo) { return {lo, std::numeric_limits<double>::infinity(), true}; }
  static constexpr ValueRange closed(double lo, double hi) { return {lo, hi}; }
  static constexpr ValueRange open_closed(double lo, double hi) { return {lo, hi, true}; }

  bool contains(double v) const;    // false for NaN and infinities
  std::string describe() const;     // "in (0, 1]", "finite and >= 0", "finite"
};

struct SliderRange {
  double min, max;
};

constexpr double kNoLimit = std::numeric_limits<double>::infinity();

// X(type, name, default, valid range, slider range, unit, help). The paper's defaults for c, m,
// alpha, beta, gamma, the lambdas, the mu's and filter_max; dt, threshold, filter_base,
// stray_patience and coarse_levels are our measured choices where the paper is silent or ambiguous (docs/solver.md).
#define PAVER_SOLVER_PARAMETERS(X)                                                                              \
  X(double, c, 0.0, ValueRange::at_least(0), SliderRange({0, 1}), "x D_ab",                                    \
    "Uniform margin: every target length grows by c D_ab (eq. 5). c + m >= 0.")                                \
  X(double, m, 0.0, ValueRange::any(), SliderRange({-1, 1}), "x D_ab",                                         \
    "Curvature-adaptive margin: target lengths grow by m D_ab where the surface is most curved (eq. 5); "      \
    "negative: denser where curved.")                                                                          \
  X(double, alpha, 10.0, ValueRange::above(0), SliderRange({0.1, 50}), "",                                     \
    "Spring stiffening at short range: k_c(r) = alpha / r^12 - beta / r^6 + gamma (eq. 8).")                    \
  X(double, beta, 5.0, ValueRange::any(), SliderRange({0, 50}), "", "The r^6 term of k_c(r) (eq. 8).")          \
  X(double, gamma, 1.0, ValueRange::any(), SliderRange({0, 10}), "", "The base spring stiffness in k_c(r) (eq. 8).") \
  X(double, lambda_r, 0.94, ValueRange::at_least(0), SliderRange({0, 1}), "",                                  \
    "Weight of the restoring (spring) force (eq. 13).")                                                        \
  X(double, lambda_l, 0.04, ValueRange::at_least(0), SliderRange({0, 1}), "",                                  \
    "Weight of the force towards the neighbours' centre (eqs. 10-11, 13).")                                    \
  X(double, lambda_g, 0.02, ValueRange::at_least(0), SliderRange({0, 1}), "",                                  \
    "Weight of the global pull towards the map's centre (eqs. 12-13); 0.001 for curvature-aware designs.")     \
  X(double, dt, 0.3, ValueRange::open_closed(0, 1), SliderRange({0.001, 1}), "",                               \
    "Step size (eq. 14). The paper uses 0.01 to 0.6 (0.5 on flat surfaces); 0.3 is the largest that measured " \
    "stable here (docs/solver.md).")                                                                           \
  X(int, iterations, 200, ValueRange::closed(0, 1000000), SliderRange({0, 100000}), "iterations",              \
    "The iteration limit of the solver.")                                                                      \
  X(double, threshold, 1e-3, ValueRange::above(0), SliderRange({1e-6, 0.1}), "x D",                            \
    "Convergence: stop when every settled particle moves less than threshold D in an iteration.")              \
  X(double, mu_compressed, 1.0, ValueRange::closed(0, 1), SliderRange({0, 1}), "",                             \
    "Learning rate of the adaptive filter for compressed springs (eq. 16).")                                   \
  X(double, mu_stretched, 0.5, ValueRange::closed(0, 1), SliderRange({0, 1}), "",                              \
    "Learning rate of the adaptive filter for stretched springs (eq. 16).")                                    \
  X(double, filter_max, 1.5, ValueRange::at_least(1), SliderRange({1, 4}), "x l_ab",                           \
    "The filter keeps a spring's target in [l_ab, filter_max l_ab] (eq. 15).")                                 \
  X(FilterBase, filter_base, FilterBase::Current, ValueRange::any(), SliderRange({0, 0}), "",                  \
    "Which l_ab the filter's clamp uses: \"current\" (recomputed every iteration from the distortion) or "     \
    "\"initial\" (fixed at initialisation); the paper is ambiguous (docs/solver.md).")                         \
  X(int, stray_patience, 10, ValueRange::closed(0, 1000000), SliderRange({0, 1000}), "iterations",             \
    "A particle pulled back onto the map this many iterations in a row is retired (0 = never).")              \
  X(int, coarse_levels, 8, ValueRange::closed(0, 16), SliderRange({0, 8}), "levels",                            \
    "Multilevel start: a large lattice first takes the shape of the same design relaxed at 2x, 4x, ... its "    \
    "spacing (at most this many levels, each of 1,000 points or more), so that it relaxes within the "          \
    "iteration limit; 0 = the paper's start from the regular lattice (docs/solver.md).")

struct SolverParams {
#define PAVER_SOLVER_FIELD(type, name, default_value, range, slider, unit, help) type name = default_value;
  PAVER_SOLVER_PARAMETERS(PAVER_SOLVER_FIELD)
#undef PAVER_SOLVER_FIELD
};

// One row of the table, for code that walks every parameter.
struct SolverParameter {
  std::string_view name;   // design.json "solver.<name>"
  std::string_view flag;   // CLI "--<flag>"
  std::variant<double SolverParams::*, int SolverParams::*, FilterBase SolverParams::*> member;
  ValueRange range;
  SliderRange slider;
  std::string_view unit;   // "" for dimensionless
  std::string_view help;
};

std::span<const SolverParameter> solver_parameters();
const SolverParameter* find_solver_parameter(std::string_view name);

// Sets parameter `p` of `params` from text ("0.25", "200", "initial"), as a command-line flag
// gives it. Returns what is wrong ("must be in (0, 1]") and leaves `params` untouched when the text
// is not a value of the parameter's type or is out of its range.
std::optional<std::string> set_solver_parameter(SolverParams& params, const SolverParameter& p, std::string_view text);

// The default as text ("0.94", "200", "current").
std::string default_text(const SolverParameter& p);

// The Markdown table in docs/parameters.md.
std::string solver_parameters_markdown();

}  // namespace paver
