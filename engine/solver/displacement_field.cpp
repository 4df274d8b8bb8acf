#include "solver/displacement_field.h"

#include <algorithm>
#include <cmath>

namespace paver {

DisplacementField::DisplacementField(glm::dvec2 lo, glm::dvec2 hi, double cell)
    : origin_(lo - glm::dvec2(cell)), cell_(cell) {
  nx_ = std::max(2, int(std::ceil((hi.x - lo.x) / cell)) + 3);
  ny_ = std::max(2, int(std::ceil((hi.y - lo.y) / cell)) + 3);
  sum_.assign(std::size_t(nx_) * ny_, glm::dvec2(0));
  weight_.assign(sum_.size(), 0.0);
}

void DisplacementField::add(glm::dvec2 at, glm::dvec2 value) {
  const glm::dvec2 g = (at - origin_) / cell_;
  const int i = std::clamp(int(std::floor(g.x)), 0, nx_ - 2), j = std::clamp(int(std::floor(g.y)), 0, ny_ - 2);
  const double fx = std::clamp(g.x - i, 0.0, 1.0), fy = std::clamp(g.y - j, 0.0, 1.0);
  const double w[4] = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy};
  const int n[4] = {node(i, j), node(i + 1, j), node(i, j + 1), node(i + 1, j + 1)};
  for (int k = 0; k < 4; ++k) {
    sum_[n[k]] += w[k] * value;
    weight_[n[k]] += w[k];
  }
}

void DisplacementField::finish() {
  // A node with a little weight holds a sample a cell away: still its best estimate.
  constexpr double kKnown = 1e-6;
  std::vector<std::uint8_t> known(sum_.size(), 0);
  bool any = false;
  for (std::size_t n = 0; n < sum_.size(); ++n)
    if (weight_[n] > kKnown) {
      sum_[n] /= weight_[n];
      known[n] = 1;
      any = true;
    }
  if (!any) {
    std::fill(sum_.begin(), sum_.end(), glm::dvec2(0));
    return;
  }
  // Grow the known region one ring at a time: a new node takes the mean of its known neighbours.
  // Each ring is found from the one before, so the growth costs the grid once.
  const int di[4] = {-1, 1, 0, 0}, dj[4] = {0, 0, -1, 1};
  std::vector<int> ring, next;
  for (int n = 0; n < int(known.size()); ++n)
    if (known[n]) ring.push_back(n);
  std::vector<std::uint8_t> queued(known);
  while (!ring.empty()) {
    next.clear();
    for (int n : ring)
      for (int k = 0; k < 4; ++k) {
        const int a = n % nx_ + di[k], b = n / nx_ + dj[k];
        if (a < 0 || b < 0 || a >= nx_ || b >= ny_ || queued[node(a, b)]) continue;
        queued[node(a, b)] = 1;
        next.push_back(node(a, b));
      }
    for (int n : next) {
      glm::dvec2 mean(0);
      int count = 0;
      for (int k = 0; k < 4; ++k) {
        const int a = n % nx_ + di[k], b = n / nx_ + dj[k];
        if (a < 0 || b < 0 || a >= nx_ || b >= ny_ || !known[node(a, b)]) continue;
        mean += sum_[node(a, b)];
        ++count;
      }
      sum_[n] = mean / double(count);  // count >= 1: it was queued from a known neighbour
    }
    for (int n : next) known[n] = 1;
    ring.swap(next);
  }
}

glm::dvec2 DisplacementField::at(glm::dvec2 p) const {
  const glm::dvec2 g = (p - origin_) / cell_;
  const int i = std::clamp(int(std::floor(g.x)), 0, nx_ - 2), j = std::clamp(int(std::floor(g.y)), 0, ny_ - 2);
  const double fx = std::clamp(g.x - i, 0.0, 1.0), fy = std::clamp(g.y - j, 0.0, 1.0);
  return (1 - fx) * (1 - fy) * sum_[node(i, j)] + fx * (1 - fy) * sum_[node(i + 1, j)] +
         (1 - fx) * fy * sum_[node(i, j + 1)] + fx * fy * sum_[node(i + 1, j + 1)];
}

}  // namespace paver
