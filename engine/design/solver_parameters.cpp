#include "design/solver_parameters.h"
#include "core/number_text.h"

#include <algorithm>
#include <charconv>
#include <system_error>
#include <cmath>
#include <string>
#include <vector>

namespace paver {
namespace {

std::string flag_of(std::string_view name) {
  std::string flag(name);
  std::replace(flag.begin(), flag.end(), '_', '-');
  return flag;
}

struct Table {
  std::vector<std::string> flags;  // storage for SolverParameter::flag
  std::vector<SolverParameter> rows;

  Table() {
#define PAVER_SOLVER_ROW(type, name, label, default_value, range, slider, unit, help) \
  rows.push_back({#name, {}, label, &SolverParams::name, range, slider, unit, help});
    PAVER_SOLVER_PARAMETERS(PAVER_SOLVER_ROW)
#undef PAVER_SOLVER_ROW
    flags.reserve(rows.size());
    for (SolverParameter& row : rows) row.flag = flags.emplace_back(flag_of(row.name));
  }
};

const Table& table() {
  static const Table instance;
  return instance;
}

}  // namespace

bool ValueRange::contains(double v) const {
  // Written as the allowed condition so that NaN, which fails every comparison, is outside.
  if (!std::isfinite(v)) return false;
  const bool above_min = min_open ? v > min : v >= min;
  const bool below_max = max_open ? v < max : v <= max;
  return above_min && below_max;
}

std::string ValueRange::describe() const {
  const bool has_min = std::isfinite(min), has_max = std::isfinite(max);
  if (has_min && has_max)
    return std::string("in ") + (min_open ? "(" : "[") + number_text(min) + ", " + number_text(max) +
           (max_open ? ")" : "]");
  if (has_min) return std::string("finite and ") + (min_open ? "> " : ">= ") + number_text(min);
  if (has_max) return std::string("finite and ") + (max_open ? "< " : "<= ") + number_text(max);
  return "finite";
}

std::span<const SolverParameter> solver_parameters() { return table().rows; }

const SolverParameter* find_solver_parameter(std::string_view name) {
  for (const SolverParameter& p : solver_parameters())
    if (p.name == name) return &p;
  return nullptr;
}

std::string default_text(const SolverParameter& p) {
  const SolverParams defaults;
  return std::visit(
      [&](auto member) -> std::string {
        const auto value = defaults.*member;
        if constexpr (std::is_same_v<decltype(value), const FilterBase>) return std::string(enum_name(value));
        else return number_text(double(value));
      },
      p.member);
}

std::optional<std::string> set_solver_parameter(SolverParams& params, const SolverParameter& p, std::string_view text) {
  if (const auto* choice = std::get_if<FilterBase SolverParams::*>(&p.member)) {
    const auto base = enum_from_name<FilterBase>(text);
    if (!base) return "must be \"current\" or \"initial\"";
    params.**choice = *base;
    return std::nullopt;
  }
  double value = 0;
  const char* end = text.data() + text.size();
  const auto parsed = std::from_chars(text.data(), end, value);
  if (text.empty() || parsed.ec != std::errc() || parsed.ptr != end) return "must be a number";
  if (!p.range.contains(value)) return "must be " + p.range.describe();
  if (const auto* integer = std::get_if<int SolverParams::*>(&p.member)) {
    if (value != std::trunc(value)) return "must be a whole number";
    params.**integer = int(value);
  } else {
    params.*std::get<double SolverParams::*>(p.member) = value;
  }
  return std::nullopt;
}

std::string solver_parameters_markdown() {
  std::string out =
      "| design.json key | CLI flag | studio field | default | valid | unit | what it does |\n"
      "|---|---|---|---|---|---|---|\n";
  for (const SolverParameter& p : solver_parameters()) {
    const bool is_choice = std::holds_alternative<FilterBase SolverParams::*>(p.member);
    const std::string valid = is_choice ? "\"current\" or \"initial\"" : p.range.describe();
    out += "| `solver." + std::string(p.name) + "` | `--" + std::string(p.flag) + "` | " + std::string(p.label) + " | " + default_text(p) + " | " +
           valid + " | " + std::string(p.unit) + " | " + std::string(p.help) + " |\n";
  }
  return out;
}

}  // namespace paver
