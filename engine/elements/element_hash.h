#pragma once
// Elements bucketed in cubic cells (CellGrid): everything within one cell width of a point lies in
// the 27 cells around it. The proximity searches build one per query set; refill inserts the
// elements it adds as it goes.
#include "elements/cell_grid.h"
#include "elements/elements.h"

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace paver {

class ElementHash {
public:
  // Buckets every element of `elements`, which must outlive the hash (it reads their positions).
  ElementHash(const Elements& elements, const CellGrid& grid) : elements_(elements), grid_(grid) {
    for (int i = 0; i < int(elements.size()); ++i) insert(i);
  }
  double cell() const { return grid_.cell; }

  // Adds element i (appended to the elements after the hash was made).
  void insert(int i) { buckets_[CellGrid::key(grid_.cell_of(elements_.position[i]))].push_back(i); }

  // Calls visit(j) for every element j in the 27 cells around `p` (i.e. at least all within one
  // cell width of it), p's own element included if it is one.
  template <class F>
  void for_each_near(const glm::dvec3& p, F&& visit) const {
    const glm::ivec3 c = grid_.cell_of(p);
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const auto it = buckets_.find(CellGrid::key(c + glm::ivec3(dx, dy, dz)));
          if (it == buckets_.end()) continue;
          for (int j : it->second) visit(j);
        }
  }

private:
  const Elements& elements_;
  CellGrid grid_;
  std::unordered_map<std::uint64_t, std::vector<int>> buckets_;
};

}  // namespace paver
