#include "io/coordinate_precision.h"
#include "core/number_text.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace paver {
namespace {

constexpr double kFloat32Rounding = 0x1.0p-24;   // of the magnitude
constexpr double kSixDigitsRounding = 5e-6;       // of the magnitude: the 6th significant digit, half

std::string three_digits(double value) { return significant_text(value); }

double smallest_diameter(const Elements& elements) {
  return *std::min_element(elements.diameter.begin(), elements.diameter.end());
}

}  // namespace

double largest_coordinate(const Elements& elements) {
  double largest = 0;
  for (std::size_t i = 0; i < elements.size(); ++i)
    for (int axis = 0; axis < 3; ++axis)
      largest = std::max(largest, std::abs(elements.position[i][axis]) + elements.diameter[i]);
  return largest;
}

bool float32_holds(const Elements& elements) {
  if (elements.size() == 0) return true;
  return largest_coordinate(elements) * kFloat32Rounding <= kCoordinateTolerance * smallest_diameter(elements);
}

std::string coordinate_rounding_warning(const Elements& elements, const std::string& stl_files,
                                        const std::string& threemf_files) {
  if (elements.size() == 0) return "";
  const double largest = largest_coordinate(elements), smallest = smallest_diameter(elements);
  // 3MF places the elements about the piece's middle (io/threemf_export.cpp): its digits round
  // with the piece's size, not with its distance from the origin.
  glm::dvec3 low(elements.position[0]), high(low);
  for (const glm::dvec3& p : elements.position) low = glm::min(low, p), high = glm::max(high, p);
  const double half_size = 0.5 * glm::length(high - low) + *std::max_element(elements.diameter.begin(), elements.diameter.end());
  std::string parts;
  const auto add = [&](const std::string& files, double error, const char* how) {
    if (files.empty() || error <= kCoordinateTolerance * smallest) return;
    parts += (parts.empty() ? "" : "; ") + files + " " + how + ", which rounds them by up to " + three_digits(error) +
             " here (" + three_digits(error / smallest) + " of the smallest element)";
  };
  add(stl_files, largest * kFloat32Rounding, "holds float32 coordinates");
  add(threemf_files, half_size * kSixDigitsRounding, "places each element with 6 significant digits");
  if (parts.empty()) return "";
  return parts + ": use placements.csv, the PLY, the OBJ or the GLB, which keep full precision" +
         (largest * kFloat32Rounding > kCoordinateTolerance * smallest ? ", or move the model near the origin" : "");
}

}  // namespace paver
