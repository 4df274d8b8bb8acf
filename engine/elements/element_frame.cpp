#include "elements/element_frame.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace paver {

ElementFrame element_frame(glm::dvec3 normal) {
  double length = glm::length(normal);
  // Lengths whose square under- or overflows: scale to the largest component first (only then, so
  // ordinary normals keep their exact arithmetic).
  if (!(length > 1e-150 && length < 1e150)) {
    const double largest = std::max({std::abs(normal.x), std::abs(normal.y), std::abs(normal.z)});
    if (largest > 0 && std::isfinite(largest)) {
      normal /= largest;
      length = glm::length(normal);
    }
  }
  const glm::dvec3 n = length > 0 && std::isfinite(length) ? normal / length : glm::dvec3(0, 0, 1);
  const double s = n.z >= 0 ? 1.0 : -1.0;
  const double k = 1.0 / (1.0 + std::abs(n.z));
  const double xy = n.x * n.y * k;
  return {{1.0 - n.x * n.x * k, -xy, -s * n.x}, {-s * xy, s * (1.0 - n.y * n.y * k), -n.y}, n};
}

}  // namespace paver
