#include "design/placement.h"

#include <cmath>
#include <numbers>

namespace paver {

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
