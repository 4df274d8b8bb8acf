#pragma once
// Numbers in messages exactly as given: whole numbers as integers (1000000, not 1e+06), others the
// shortest text that reads back as the same double.
#include <charconv>
#include <cmath>
#include <cstdio>
#include <string>

namespace paver {

inline std::string number_text(double value) {
  if (std::isnan(value)) return "NaN";  // not "-nan": a NaN has no sign worth telling a user
  if (std::isfinite(value) && value == std::trunc(value) && std::abs(value) < 1e15)
    return std::to_string(static_cast<long long>(value));
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

// `value` to `digits` significant digits (%g) for a message: 0.0123, 1.23e+06; "NaN" and
// "infinity" rather than the C library's "-nan" and "inf".
inline std::string significant_text(double value, int digits = 3) {
  if (std::isnan(value)) return "NaN";
  if (std::isinf(value)) return value > 0 ? "infinity" : "-infinity";
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
  return buffer;
}

// A large figure for people: rounded to 3 significant digits and grouped in thousands
// (2,670,000, not 2.67e+06); below 100, one decimal at most (8.4).
inline std::string rounded_figure_text(double value) {
  if (!std::isfinite(value)) return significant_text(value);
  if (std::abs(value) < 100) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.1f", value);
    std::string text = buffer;
    if (text.size() > 2 && text.compare(text.size() - 2, 2, ".0") == 0) text.resize(text.size() - 2);
    return text;
  }
  const double magnitude = std::pow(10.0, std::floor(std::log10(std::abs(value))) - 2);
  const long long whole = static_cast<long long>(std::llround(value / magnitude) * magnitude);
  std::string digits = std::to_string(whole < 0 ? -whole : whole), grouped;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) grouped += ',';
    grouped += digits[i];
  }
  return (whole < 0 ? "-" : "") + grouped;
}

// A duration for people: "45 s", "12 minutes", "13.6 hours", "2.1 days".
inline std::string duration_text(double seconds) {
  if (!std::isfinite(seconds)) return significant_text(seconds) + " s";
  if (seconds < 90) return rounded_figure_text(seconds) + " s";
  if (seconds < 90 * 60) return rounded_figure_text(std::round(seconds / 60)) + " minutes";
  if (seconds < 48 * 3600) return rounded_figure_text(seconds / 3600) + " hours";
  return rounded_figure_text(seconds / 86400) + " days";
}

// "1 problem", "3 problems": a count with its noun in the right number.
inline std::string count_text(long long count, const std::string& singular, const std::string& plural) {
  return std::to_string(count) + " " + (count == 1 ? singular : plural);
}

}  // namespace paver
