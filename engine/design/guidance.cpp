#include "design/guidance.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace paver {

double guidance_factor(const std::vector<GuidanceDab>& dabs, glm::dvec2 uv) {
  double change = 0;
  for (const GuidanceDab& d : dabs) {
    const double x = glm::length(uv - d.uv) / d.radius;
    if (x >= 1) continue;
    const double fade = (1 - x * x) * (1 - x * x);  // 1 at the centre, flat at both ends
    change += d.strength * fade;
  }
  return std::clamp(1 + change, kGuidanceMin, kGuidanceMax);
}

}  // namespace paver
