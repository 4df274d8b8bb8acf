#include "pattern/placement.h"

#include <cmath>
#include <numbers>

namespace paver {

std::string_view band_rows_name(BandRows rows) {
  return rows == BandRows::Across ? "across" : rows == BandRows::Along ? "along" : "auto";
}

std::string_view align_axis_name(AlignAxis axis) {
  switch (axis) {
    case AlignAxis::X: return "x";
    case AlignAxis::Y: return "y";
    case AlignAxis::Z: return "z";
    case AlignAxis::None: break;
  }
  return "none";
}

std::optional<AlignAxis> align_axis_from_name(std::string_view name) {
  for (AlignAxis a : {AlignAxis::None, AlignAxis::X, AlignAxis::Y, AlignAxis::Z})
    if (name == align_axis_name(a)) return a;
  return std::nullopt;
}

glm::dvec2 Placement::map_to_pattern(glm::dvec2 q) const {
  const double a = rotation_deg * std::numbers::pi / 180.0;
  const double c = std::cos(a), s = std::sin(a);
  const glm::dvec2 scaled = scale * q;
  return glm::dvec2(c * scaled.x - s * scaled.y, s * scaled.x + c * scaled.y) + offset;
}

glm::dvec2 Placement::pattern_to_map(glm::dvec2 p) const {
  const double a = rotation_deg * std::numbers::pi / 180.0;
  const double c = std::cos(a), s = std::sin(a);
  const glm::dvec2 d = p - offset;
  return glm::dvec2(c * d.x + s * d.y, -s * d.x + c * d.y) / scale;
}

}  // namespace paver
