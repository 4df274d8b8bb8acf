#include "elements/element_proximity.h"

#include "elements/contact_rule.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>

namespace paver {
namespace {

// Elements bucketed in cubic cells at least one largest diameter wide, so any touching pair
// lies in the same or adjacent cells.
class ElementHash {
public:
  ElementHash(const Elements& e, double cell) : elements_(e), cell_(cell) {
    for (int i = 0; i < int(e.size()); ++i) buckets_[key(cell_of(e.position[i]))].push_back(i);
  }
  template <class F>
  void for_each_near(int i, F&& visit) const {
    const glm::ivec3 c = cell_of(elements_.position[i]);
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const auto it = buckets_.find(key(c + glm::ivec3(dx, dy, dz)));
          if (it == buckets_.end()) continue;
          for (int j : it->second)
            if (j != i) visit(j);
        }
  }

private:
  glm::ivec3 cell_of(const glm::dvec3& p) const {
    return glm::ivec3(int(std::floor(p.x / cell_)), int(std::floor(p.y / cell_)), int(std::floor(p.z / cell_)));
  }
  static std::uint64_t key(glm::ivec3 c) {
    return (std::uint64_t(std::uint32_t(c.x) & 0x1fffff) << 42) | (std::uint64_t(std::uint32_t(c.y) & 0x1fffff) << 21) |
           std::uint64_t(std::uint32_t(c.z) & 0x1fffff);
  }
  const Elements& elements_;
  double cell_;
  std::unordered_map<std::uint64_t, std::vector<int>> buckets_;
};

double largest_diameter(const Elements& e) {
  double d = 0;
  for (double x : e.diameter) d = std::max(d, x);
  return d > 0 ? d : 1;
}

}  // namespace

std::vector<Collision> find_collisions(const Elements& elements) {
  std::vector<Collision> out;
  const ElementHash hash(elements, largest_diameter(elements));
  for (int i = 0; i < int(elements.size()); ++i) {
    hash.for_each_near(i, [&](int j) {
      if (j < i) return;
      const double reach = contact_distance(elements.diameter[i], elements.diameter[j]);
      const double d = glm::length(elements.position[i] - elements.position[j]);
      if (elements_collide(d, elements.diameter[i], elements.diameter[j])) out.push_back({i, j, d, 1 - d / reach});
    });
  }
  std::sort(out.begin(), out.end(), [](const Collision& a, const Collision& b) {
    return a.i != b.i ? a.i < b.i : a.j < b.j;
  });
  return out;
}

std::vector<double> nearest_neighbor_ratios(const Elements& elements) {
  const int n = int(elements.size());
  std::vector<double> ratio(n, std::numeric_limits<double>::infinity());
  if (n < 2) return ratio;
  // Search cells two diameters wide so loose patterns (ratios up to ~2) find their neighbour in
  // the 27 cells around them. Every element outside those cells is at least `cell` away, so a
  // ratio found below cell / reach_max is the true minimum; above it (a loose element, or none
  // found) the element is scanned against all others.
  const double largest = largest_diameter(elements);
  const double cell = 2 * largest;
  const ElementHash hash(elements, cell);
  for (int i = 0; i < n; ++i) {
    hash.for_each_near(i, [&](int j) {
      const double reach = contact_distance(elements.diameter[i], elements.diameter[j]);
      ratio[i] = std::min(ratio[i], glm::length(elements.position[i] - elements.position[j]) / reach);
    });
  }
  for (int i = 0; i < n; ++i) {
    const double proven = cell / contact_distance(elements.diameter[i], largest);
    if (ratio[i] <= proven) continue;
    for (int j = 0; j < n; ++j)
      if (j != i) {
        const double reach = contact_distance(elements.diameter[i], elements.diameter[j]);
        ratio[i] = std::min(ratio[i], glm::length(elements.position[i] - elements.position[j]) / reach);
      }
  }
  return ratio;
}

}  // namespace paver
