#include "number_rules.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <utility>

namespace paver::studio {
namespace {

std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", x);
  return text;
}

std::string with_unit(double x, const NumberRule& rule) { return number(x) + (rule.unit.empty() ? "" : " " + rule.unit); }

std::vector<std::string>& refusals() {
  static std::vector<std::string> lines;
  return lines;
}

}  // namespace

NumberRule NumberRule::of(Key key, std::string unit) {
  const DesignKey& k = design_key(key);
  // A note that only repeats the unit says nothing the range does not.
  std::string hint = k.range_note == k.unit ? std::string() : std::string(k.range_note);
  return NumberRule{k.range, std::move(unit), {}, std::move(hint)};
}

NumberRule& NumberRule::below(double hi, std::string reason) {
  if (!(hi < range.max)) return *this;
  range.max = hi;
  range.max_open = true;
  hi_reason = std::move(reason);
  return *this;
}

std::string range_text(const NumberRule& rule) {
  const ValueRange& r = rule.range;
  const bool has_lo = std::isfinite(r.min), has_hi = std::isfinite(r.max);
  if (has_lo && has_hi && !r.min_open && !r.max_open)
    return "a value from " + number(r.min) + " to " + with_unit(r.max, rule);
  if (has_lo && has_hi)
    return std::string("a value ") + (r.min_open ? "above " : "of at least ") + with_unit(r.min, rule) +
           (r.max_open ? " and below " : " and at most ") + with_unit(r.max, rule);
  if (has_lo) return std::string("a value ") + (r.min_open ? "above " : "of at least ") + with_unit(r.min, rule);
  if (has_hi) return std::string("a value ") + (r.max_open ? "below " : "of at most ") + with_unit(r.max, rule);
  return "a number";
}

TypedNumber read_typed_number(std::string_view label, std::string_view typed, const NumberRule& rule) {
  // Spaces around the number are a person's, not part of it.
  while (!typed.empty() && (typed.front() == ' ' || typed.front() == '\t')) typed.remove_prefix(1);
  while (!typed.empty() && (typed.back() == ' ' || typed.back() == '\t')) typed.remove_suffix(1);
  const std::string text(typed);
  const std::string head = std::string(label) + " '" + text + "'";
  const auto refuse = [&](const std::string& why) {
    std::string line = head + ": " + why + "; give " + range_text(rule);
    if (!rule.hi_reason.empty() && why.find("large") != std::string::npos) line += " (" + rule.hi_reason + ")";
    if (!rule.hint.empty()) line += " (" + rule.hint + ")";
    return TypedNumber{std::nullopt, line};
  };
  if (text.empty()) return refuse("no number was typed");
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size()) return refuse("is not a number");
  if (!std::isfinite(value) || errno == ERANGE) return refuse("is not a finite number");
  const ValueRange& r = rule.range;
  if (value < r.min || (r.min_open && value == r.min)) return refuse("too small");
  if (value > r.max || (r.max_open && value == r.max)) return refuse("too large");
  return TypedNumber{value, {}};
}

void post_refusal(std::string line) { refusals().push_back(std::move(line)); }

std::vector<std::string> take_refusals() { return std::exchange(refusals(), {}); }

}  // namespace paver::studio
