#include "solver/guidance_field.h"

namespace paver {

void apply_guidance(SpringSystem& system, const Pattern& pattern, const std::vector<GuidanceDab>& dabs) {
  if (dabs.empty()) return;
  const GuidanceField field(dabs);
  // The pattern's own springs come first in the system, in the pattern's edge order.
  for (int e = 0; e < pattern.edge_count(); ++e) {
    const glm::dvec2 middle = 0.5 * (pattern.points[std::size_t(pattern.edge_a[std::size_t(e)])] +
                                     pattern.points[std::size_t(pattern.edge_b[std::size_t(e)])]);
    system.rest_length[std::size_t(e)] = float(system.rest_length[std::size_t(e)] * field.factor(middle));
  }
}

}  // namespace paver
