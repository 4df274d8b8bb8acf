#pragma once
// The designer's guidance field (the paper's "user-specific guidance field", its future work):
// dabs of a brush painted on the map that make the pattern looser (strength > 0) or denser
// (< 0) where they lie. design.json "guidance"; applied by solver/guidance_field.h.
#include <glm/vec2.hpp>

#include <vector>

namespace paver {

struct GuidanceDab {
  glm::dvec2 uv{0};     // centre, in the frame of the map the pattern is laid on
  double radius = 1;    // surface units
  double strength = 0;  // the spacing's change at the centre: +0.3 = 30% looser, -0.2 = 20% denser
};

// The most one place may be changed, however many dabs overlap there: half to twice the spacing.
inline constexpr double kGuidanceMin = 0.5, kGuidanceMax = 2.0;

// The factor on the spacing at `uv`: 1 + the dabs' strengths, each fading smoothly to 0 at its
// radius, clamped to [kGuidanceMin, kGuidanceMax].
double guidance_factor(const std::vector<GuidanceDab>& dabs, glm::dvec2 uv);

}  // namespace paver
