#pragma once
// The section 5 solver parameters, each described once. PAVER_SOLVER_PARAMETERS below is the
// table: one row per parameter with its type, name (design.json key "solver.<name>", CLI flag
// --<name with '-' for '_'>), plain-word label, default, valid range, slider range, unit and help. From it come the
// SolverParams struct, the design.json reader and writer, validation, the CLI flags, the studio's
// panel, the script's `set solver.<name>` and the docs table (docs/parameters.md, checked by a test).
// Adding a parameter is adding a row (and using it in the solver).
#include "core/enum_names.h"

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

PAVER_ENUM_NAMES(FilterBase, {FilterBase::Current, "current"}, {FilterBase::Initial, "initial"});

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

// The ranges are bounded so that every value, and the forces and lengths it makes, stays within
// float32, the GPU's type: c = 1e30 made positions non-finite (an internal error, not a refusal).
// A hundred D of extra room or a stiffness of a million is far past any design that paves.
// X(type, name, label, default, valid range, slider range, unit, help). The label and the help say
// in plain words what a designer changes (the studio's field and tooltip); the paper's symbol and
// equation follow in brackets. The paper's defaults for c, m, alpha, beta, gamma, the lambdas, the
// mu's and filter_max; dt, threshold, filter_base, stray_patience and coarse_levels are our
// measured choices where the paper is silent or ambiguous (docs/solver.md).
#define PAVER_SOLVER_PARAMETERS(X)                                                                              \
  X(double, c, "extra spacing", 0.0, ValueRange::closed(0, 100), SliderRange({0, 1}), "x pattern length D_ab",    \
    "Extra room between neighbouring elements everywhere, as a fraction of their distance in the regular "    \
    "pattern (D_ab: D along a tessellation edge): 0.1 sets every pair 10% farther apart (the paper's c, "     \
    "eq. 5). c + m must stay >= 0.")                                                                          \
  X(double, m, "extra spacing where curved", 0.0, ValueRange::closed(-100, 100), SliderRange({-1, 1}),                     \
    "x pattern length D_ab",                                                                                  \
    "Extra room where the surface bends most, fading to none where it is flat, as a fraction of the pair's "  \
    "distance in the pattern; negative packs elements closer where it is curved (the paper's m, eq. 5).")    \
  X(double, alpha, "close-range stiffness", 10.0, ValueRange::open_closed(0, 1e6), SliderRange({0.1, 50}), "no unit",     \
    "How hard a spring pushes back when two elements come much closer than their target (alpha in the "       \
    "spring stiffness k_c(r) = alpha / r^12 - beta / r^6 + gamma, eq. 8).")                                    \
  X(double, beta, "near-range softening", 5.0, ValueRange::closed(-1e6, 1e6), SliderRange({0, 50}), "no unit",             \
    "How much a spring softens just inside its target length (beta, the r^6 term of eq. 8).")                 \
  X(double, gamma, "base stiffness", 1.0, ValueRange::closed(-1e6, 1e6), SliderRange({0, 10}), "no unit",                  \
    "The springs' stiffness at their target length (gamma in eq. 8).")                                         \
  X(double, lambda_r, "keep the spacing", 0.94, ValueRange::closed(0, 1e6), SliderRange({0, 1}), "weight",        \
    "How strongly each element keeps its distance to its pattern neighbours, against the two pulls below "    \
    "(the restoring force's weight lambda_r, eq. 13).")                                                        \
  X(double, lambda_l, "even out", 0.04, ValueRange::closed(0, 1e6), SliderRange({0, 1}), "weight",                \
    "How strongly each element moves towards the middle of its neighbours, evening the pattern out "          \
    "(lambda_l, eqs. 10-11, 13).")                                                                             \
  X(double, lambda_g, "hold together", 0.02, ValueRange::closed(0, 1e6), SliderRange({0, 1}), "weight",           \
    "How strongly the whole pattern is pulled towards the map's centre, so that it neither drifts nor "       \
    "spreads off the surface (lambda_g, eqs. 12-13); 0.001 for curvature-aware designs.")                      \
  X(double, dt, "step size", 0.3, ValueRange::open_closed(0, 1), SliderRange({0.001, 1}), "no unit",          \
    "How far the elements move in one iteration: larger settles sooner but can overshoot (dt, eq. 14). "      \
    "The paper uses 0.01 to 0.6 (0.5 on flat surfaces); 0.3 is the largest that measured stable here "       \
    "(docs/solver.md).")                                                                                       \
  X(int, iterations, "iteration limit", 200, ValueRange::closed(0, 1000000), SliderRange({0, 100000}),         \
    "iterations", "The most iterations a run takes; it stops sooner once settled (below).")                    \
  X(double, threshold, "settled below", 1e-3, ValueRange::open_closed(0, 1), SliderRange({1e-6, 0.1}), "x spacing D",   \
    "The run stops when every settled element moves less than this fraction of D in an iteration.")            \
  X(double, mu_compressed, "squeezed springs adapt", 1.0, ValueRange::closed(0, 1), SliderRange({0, 1}),       \
    "rate, 0 to 1",                                                                                             \
    "How fast a spring pressed shorter than its target lets the target follow, where the map squeezes the "   \
    "surface: 1 at once, 0 never (the adaptive filter's mu, eq. 16).")                                         \
  X(double, mu_stretched, "stretched springs adapt", 0.75, ValueRange::closed(0, 1), SliderRange({0, 1}),       \
    "rate, 0 to 1",                                                                                             \
    "How fast a spring pulled longer than its target lets the target follow, where the map stretches the "    \
    "surface: 1 at once, 0 never (the adaptive filter's mu, eq. 16). The paper uses 0.5; 0.75 measured "       \
    "fuller pavements on large patterns (docs/solver.md).")                                                     \
  X(double, filter_max, "most a spring adapts", 1.5, ValueRange::closed(1, 1000), SliderRange({1, 4}),             \
    "x rest length", "A spring's target may follow the map up to this many times its rest length l_ab, and "   \
    "never below it (eq. 15).")                                                                                \
  X(FilterBase, filter_base, "rest length from", FilterBase::Current, ValueRange::any(), SliderRange({0, 0}),  \
    "choice",                                                                                                   \
    "Which rest length l_ab the limit above uses: \"current\" (recomputed every iteration from the "           \
    "distortion) or \"initial\" (fixed at the start); the paper is ambiguous (docs/solver.md).")               \
  X(int, stray_patience, "drop strays after", 10, ValueRange::closed(0, 1000000), SliderRange({0, 1000}),     \
    "iterations", "An element pushed off the map and pulled back this many iterations in a row is dropped "    \
    "(0 = never).")                                                                                            \
  X(int, coarse_levels, "coarse start levels", 8, ValueRange::closed(0, 16), SliderRange({0, 8}), "levels",   \
    "Multilevel start: a large lattice first takes the shape of the same design relaxed at 2x, 4x, ... its "    \
    "spacing (at most this many levels, each of 1,000 points or more), so that it relaxes within the "          \
    "iteration limit; 0 = the paper's start from the regular lattice (docs/solver.md).")

struct SolverParams {
#define PAVER_SOLVER_FIELD(type, name, label, default_value, range, slider, unit, help) type name = default_value;
  PAVER_SOLVER_PARAMETERS(PAVER_SOLVER_FIELD)
#undef PAVER_SOLVER_FIELD
};

// One row of the table, for code that walks every parameter.
struct SolverParameter {
  std::string_view name;   // design.json "solver.<name>"
  std::string_view flag;   // CLI "--<flag>"
  std::string_view label;  // plain words, the studio's field
  std::variant<double SolverParams::*, int SolverParams::*, FilterBase SolverParams::*> member;
  ValueRange range;
  SliderRange slider;
  std::string_view unit;   // what the number counts or is a multiple of
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
