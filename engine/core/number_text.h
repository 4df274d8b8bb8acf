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

// "1 problem", "3 problems": a count with its noun in the right number.
inline std::string count_text(long long count, const std::string& singular, const std::string& plural) {
  return std::to_string(count) + " " + (count == 1 ? singular : plural);
}

}  // namespace paver
