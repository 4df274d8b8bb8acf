#include "design/guidance.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace paver {
namespace {

// One dab's change at `uv`: its strength, fading smoothly to 0 at its radius.
double dab_change(const GuidanceDab& d, glm::dvec2 uv) {
  const double x = glm::length(uv - d.uv) / d.radius;
  if (!(x < 1)) return 0;
  const double fade = (1 - x * x) * (1 - x * x);  // 1 at the centre, flat at both ends
  return d.strength * fade;
}

// A dab over more cells than this is read by every point instead of bucketed.
constexpr long long kMaxCellsPerDab = 64;

}  // namespace

double guidance_factor(const std::vector<GuidanceDab>& dabs, glm::dvec2 uv) {
  double change = 0;
  for (const GuidanceDab& d : dabs) change += dab_change(d, uv);
  return std::clamp(1 + change, kGuidanceMin, kGuidanceMax);
}

GuidanceField::GuidanceField(const std::vector<GuidanceDab>& dabs) : dabs_(dabs) {
  if (dabs.empty()) return;
  // Cells the size of the typical (median) dab: a brush stroke's dabs are alike.
  std::vector<double> radii;
  glm::dvec2 lo(std::numeric_limits<double>::infinity());
  for (const GuidanceDab& d : dabs) radii.push_back(d.radius), lo = glm::min(lo, d.uv - d.radius);
  std::nth_element(radii.begin(), radii.begin() + long(radii.size() / 2), radii.end());
  cell_ = radii[radii.size() / 2];
  origin_ = lo;
  if (!(cell_ > 0) || !std::isfinite(cell_) || !std::isfinite(lo.x) || !std::isfinite(lo.y)) {
    for (int i = 0; i < int(dabs.size()); ++i) unbucketed_.push_back(i);
    return;
  }
  for (int i = 0; i < int(dabs.size()); ++i) {
    const GuidanceDab& d = dabs[std::size_t(i)];
    const glm::dvec2 a = glm::floor((d.uv - d.radius - origin_) / cell_), b = glm::floor((d.uv + d.radius - origin_) / cell_);
    if (!((b.x - a.x + 1) * (b.y - a.y + 1) <= double(kMaxCellsPerDab))) {
      unbucketed_.push_back(i);
      continue;
    }
    for (long long y = (long long)a.y; y <= (long long)b.y; ++y)
      for (long long x = (long long)a.x; x <= (long long)b.x; ++x) cells_[key(x, y)].push_back(i);
  }
}

std::uint64_t GuidanceField::key(long long x, long long y) const {
  return (std::uint64_t(x) << 32) ^ std::uint64_t(std::uint32_t(y));
}

double GuidanceField::factor(glm::dvec2 uv) const {
  if (dabs_.empty()) return 1;
  std::vector<int> near = unbucketed_;
  const glm::dvec2 c = glm::floor((uv - origin_) / cell_);
  if (std::isfinite(c.x) && std::isfinite(c.y) && std::abs(c.x) < 1e15 && std::abs(c.y) < 1e15)
    if (const auto it = cells_.find(key((long long)c.x, (long long)c.y)); it != cells_.end())
      near.insert(near.end(), it->second.begin(), it->second.end());
  std::sort(near.begin(), near.end());  // the dabs' order, as guidance_factor sums them
  double change = 0;
  for (const int i : near) change += dab_change(dabs_[std::size_t(i)], uv);
  return std::clamp(1 + change, kGuidanceMin, kGuidanceMax);
}

}  // namespace paver
