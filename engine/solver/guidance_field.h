#pragma once
// The guidance field on the spring system: each spring's rest length D_ab is scaled by the
// design's guidance factor at its midpoint in the laid-out pattern, so the solver pulls the
// pattern looser or denser there (eq. 4-6 build on D_ab, so curvature adaptivity multiplies in).
// The field is attached to the springs where the pattern was laid out: particles carry it along
// as they relax, which for a painted region a few spacings wide is where it was painted. Contact
// still wins: a region painted denser than the stones allow stops at contact.
#include "design/guidance.h"
#include "pattern/pattern.h"
#include "solver/spring_system.h"

#include <vector>

namespace paver {

void apply_guidance(SpringSystem& system, const Pattern& pattern, const std::vector<GuidanceDab>& dabs);

}  // namespace paver
