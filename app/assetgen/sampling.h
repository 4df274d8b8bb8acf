#pragma once
// Arc-length sampling: where to put nodes so that 3D spacing comes out even.
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

namespace paver::assetgen {

// Polyline with cumulative arc length, evaluated by the fraction of its length.
class Polyline {
 public:
  explicit Polyline(std::vector<glm::dvec2> points) : p_(std::move(points)), s_(p_.size(), 0.0) {
    for (std::size_t i = 1; i < p_.size(); ++i) s_[i] = s_[i - 1] + glm::distance(p_[i - 1], p_[i]);
  }
  double length() const { return s_.back(); }
  glm::dvec2 at(double fraction) const {
    const double s = std::clamp(fraction, 0.0, 1.0) * length();
    const auto it = std::upper_bound(s_.begin(), s_.end(), s);
    const std::size_t i = std::clamp<std::size_t>(it - s_.begin(), 1, s_.size() - 1);
    const double w = (s - s_[i - 1]) / std::max(s_[i] - s_[i - 1], 1e-300);
    return glm::mix(p_[i - 1], p_[i], std::clamp(w, 0.0, 1.0));
  }

 private:
  std::vector<glm::dvec2> p_;
  std::vector<double> s_;
};

// Cumulative integral of a positive density over [lo, hi], inverted to place nodes at equal
// steps of it: turns "even 3D spacing" into parameter values.
class EvenSpacing {
 public:
  EvenSpacing(double lo, double hi, const std::function<double(double)>& density, int samples = 4096)
      : lo_(lo), hi_(hi), cum_(samples + 1, 0.0) {
    const double dx = (hi - lo) / samples;
    double prev = density(lo);
    for (int i = 1; i <= samples; ++i) {
      const double cur = density(lo + i * dx);
      cum_[i] = cum_[i - 1] + 0.5 * (prev + cur) * dx;
      prev = cur;
    }
  }
  double length() const { return cum_.back(); }
  // Parameter where the integral reaches `fraction` of its total.
  double at(double fraction) const {
    const double target = std::clamp(fraction, 0.0, 1.0) * length();
    const auto it = std::lower_bound(cum_.begin(), cum_.end(), target);
    const std::size_t i = std::clamp<std::size_t>(it - cum_.begin(), 1, cum_.size() - 1);
    const double w = (target - cum_[i - 1]) / std::max(cum_[i] - cum_[i - 1], 1e-300);
    const double dx = (hi_ - lo_) / static_cast<double>(cum_.size() - 1);
    return lo_ + (static_cast<double>(i - 1) + std::clamp(w, 0.0, 1.0)) * dx;
  }
  // n + 1 nodes from lo to hi, ends exact.
  std::vector<double> nodes(int n) const {
    std::vector<double> x(n + 1);
    for (int i = 0; i <= n; ++i) x[i] = at(static_cast<double>(i) / n);
    x.front() = lo_;
    x.back() = hi_;
    return x;
  }

 private:
  double lo_, hi_;
  std::vector<double> cum_;
};

}  // namespace paver::assetgen
