#include "report/ring_size.h"

#include "core/input_error.h"
#include "core/number_text.h"
#include "core/printable.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>
#include <optional>
#include <cctype>

namespace paver {
namespace {

constexpr double kUsZeroMm = 11.63, kUsStepMm = 0.8128, kUsLargest = 16;
constexpr double kEuSmallest = 38, kEuLargest = 76;
constexpr double kUkAMm = 37.5, kUkHalfStepMm = 0.625;  // circumference
constexpr int kUkHalfSizes = 2 * 26;                    // A to Z 1/2

std::optional<double> number_in(const std::string& text) {
  double value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

// UK sizes as half steps from A: "A" 0, "A1/2" 1, ..., "Z1/2" 51.
std::optional<int> uk_half_steps(std::string text) {
  if (text.empty()) return std::nullopt;
  const char letter = char(std::toupper(static_cast<unsigned char>(text[0])));
  if (letter < 'A' || letter > 'Z') return std::nullopt;
  const std::string rest = text.substr(1);
  int half = 0;
  if (rest == "1/2" || rest == ".5" || rest == "\xc2\xbd" || rest == " 1/2") half = 1;  // also "½"
  else if (!rest.empty()) return std::nullopt;
  return 2 * (letter - 'A') + half;
}

std::string uk_size_text(int half_steps) {
  return std::string(1, char('A' + half_steps / 2)) + (half_steps % 2 ? "1/2" : "");
}

double uk_diameter(int half_steps) { return (kUkAMm + kUkHalfStepMm * half_steps) / std::numbers::pi; }

}  // namespace

double ring_inside_diameter_mm(RingSizeSystem system, const std::string& size) {
  const std::string given = "--ring-size " + std::string(enum_name(system)) + " " + printable(size) + ": ";
  if (system == RingSizeSystem::UK) {
    const std::optional<int> steps = uk_half_steps(size);
    if (!steps) throw InputError(given + "a UK size is a letter A to Z, with 1/2 for a half size (N, N1/2)");
    return uk_diameter(*steps);
  }
  const std::optional<double> value = number_in(size);
  if (system == RingSizeSystem::US) {
    if (!value || *value < 0 || *value > kUsLargest)
      throw InputError(given + "a US size is a number from 0 to 16 (7, 7.5, 7.25)");
    return kUsZeroMm + kUsStepMm * *value;
  }
  if (!value || *value < kEuSmallest || *value > kEuLargest)
    throw InputError(given + "an EU size is the inside circumference in mm, from 38 to 76 (54)");
  return *value / std::numbers::pi;
}

nlohmann::json nearest_ring_sizes_json(double inside_diameter_mm) {
  const double us = std::clamp(std::round((inside_diameter_mm - kUsZeroMm) / kUsStepMm * 4) / 4, 0.0, kUsLargest);
  const double eu = std::clamp(std::round(inside_diameter_mm * std::numbers::pi * 10) / 10, kEuSmallest, kEuLargest);
  const int uk = std::clamp(int(std::lround((inside_diameter_mm * std::numbers::pi - kUkAMm) / kUkHalfStepMm)), 0,
                            kUkHalfSizes - 1);
  const auto row = [](const std::string& size, double diameter) {
    return nlohmann::json{{"size", size}, {"inside_diameter_mm", std::round(diameter * 100) / 100}};
  };
  return {{"US", row(number_text(us), kUsZeroMm + kUsStepMm * us)},
          {"EU", row(number_text(eu), eu / std::numbers::pi)},
          {"UK", row(uk_size_text(uk), uk_diameter(uk))}};
}

}  // namespace paver
