#pragma once
// The designer's guidance field (the paper's "user-specific guidance field", its future work):
// dabs of a brush painted on the map that make the pattern looser (strength > 0) or denser
// (< 0) where they lie. design.json "guidance"; applied by solver/guidance_field.h.
#include <glm/vec2.hpp>

#include <cstdint>
#include <unordered_map>
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

// The same for many points: the dabs bucketed by place, so that a point reads only the dabs that
// can reach it (a stroke of 10,000 dabs over a million springs was 10^10 distance tests). Sums in
// the dabs' order, so every factor equals guidance_factor's bit for bit.
class GuidanceField {
public:
  explicit GuidanceField(const std::vector<GuidanceDab>& dabs);
  double factor(glm::dvec2 uv) const;

private:
  std::uint64_t key(long long x, long long y) const;
  const std::vector<GuidanceDab>& dabs_;
  double cell_ = 1;
  glm::dvec2 origin_{0};
  std::unordered_map<std::uint64_t, std::vector<int>> cells_;
  std::vector<int> unbucketed_;  // dabs too large for the grid: read by every point
};

}  // namespace paver
