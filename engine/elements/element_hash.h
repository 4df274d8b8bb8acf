#pragma once
// Points bucketed in cubic cells (CellGrid): everything within one cell width of a point lies in
// the 27 cells around it. The proximity searches build one over elements per query set; refill
// inserts the elements it adds as it goes; the adaptive pattern's seed thinning and contact
// search use it over bare positions.
#include "elements/cell_grid.h"
#include "elements/elements.h"

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace paver {

class ElementHash {
public:
  enum class Fill { All, None };

  // Buckets every element of `elements`, which must outlive the hash (it reads their positions).
  ElementHash(const Elements& elements, const CellGrid& grid) : ElementHash(elements.position, grid, Fill::All) {}
  // Over bare positions (which must outlive the hash): all of them, or none until inserted.
  ElementHash(const std::vector<glm::dvec3>& positions, const CellGrid& grid, Fill fill)
      : positions_(positions), grid_(grid) {
    if (fill == Fill::All)
      for (int i = 0; i < int(positions.size()); ++i) insert(i);
  }
  double cell() const { return grid_.cell; }

  // Adds point i (e.g. an element appended after the hash was made).
  void insert(int i) { buckets_[CellGrid::key(grid_.cell_of(positions_[i]))].push_back(i); }

  // Calls visit(j) for every element j in the 27 cells around `p` (i.e. at least all within one
  // cell width of it), p's own element included if it is one.
  template <class F>
  void for_each_near(const glm::dvec3& p, F&& visit) const {
    grid_.for_each_key_around(p, [&](std::uint64_t key) {
      const auto it = buckets_.find(key);
      if (it != buckets_.end())
        for (int j : it->second) visit(j);
    });
  }

private:
  const std::vector<glm::dvec3>& positions_;
  CellGrid grid_;
  std::unordered_map<std::uint64_t, std::vector<int>> buckets_;
};

}  // namespace paver
