#pragma once
// Cubic cells over a box of 3D points, for the spatial hashes of elements and boundary segments.
// Cells are counted from the box's lowest corner and are never smaller than a millionth of its
// largest side, so cell indices stay in [0, 1e6] (inside the key's 21 bits per axis) whatever the
// sizes and wherever the part is: tiny elements on a big part, or a part far from the origin,
// would otherwise overflow them.
#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace paver {

struct CellGrid {
  glm::dvec3 origin{0.0};
  double cell = 1;

  // `lo`, `hi`: the box all points lie in; `min_cell`: the cell size wanted (> 0).
  CellGrid(glm::dvec3 lo, glm::dvec3 hi, double min_cell) : origin(lo) {
    const glm::dvec3 size = hi - lo;
    cell = std::max(min_cell, 1e-6 * std::max({size.x, size.y, size.z}));
    if (!(cell > 0)) cell = 1;
  }

  glm::ivec3 cell_of(const glm::dvec3& p) const {
    const glm::dvec3 r = (p - origin) / cell;
    return glm::ivec3(int(std::floor(r.x)), int(std::floor(r.y)), int(std::floor(r.z)));
  }

  // Calls visit(key) for the 27 cells around p's cell (its own included): everything within one
  // cell width of p lies in them.
  template <class F>
  void for_each_key_around(const glm::dvec3& p, F&& visit) const {
    const glm::ivec3 c = cell_of(p);
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) visit(key(c + glm::ivec3(dx, dy, dz)));
  }

  static std::uint64_t key(glm::ivec3 c) {
    return (std::uint64_t(std::uint32_t(c.x) & 0x1fffff) << 42) | (std::uint64_t(std::uint32_t(c.y) & 0x1fffff) << 21) |
           std::uint64_t(std::uint32_t(c.z) & 0x1fffff);
  }
};

}  // namespace paver
