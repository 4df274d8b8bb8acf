#pragma once
// Points bucketed in cubic cells (CellGrid): everything within one cell width of a point lies in
// the 27 cells around it. The proximity searches build one over elements per query set; refill
// inserts the elements it adds as it goes; the adaptive pattern's seed thinning and contact
// search use it over bare positions.
#include "core/cell_grid.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <utility>
#include <vector>

namespace paver {

class PointHash {
public:
  enum class Fill { All, None };

  // Over `positions` (which must outlive the hash: it reads them), e.g. elements' centres: all of
  // them, or none until inserted.
  PointHash(const std::vector<glm::dvec3>& positions, const CellGrid& grid, Fill fill = Fill::All)
      : positions_(positions), grid_(grid) {
    if (fill == Fill::All) {
      grow(2 * positions.size());
      for (int i = 0; i < int(positions.size()); ++i) insert(i);
    }
  }
  double cell() const { return grid_.cell; }

  // Adds point i (e.g. an element appended after the hash was made).
  void insert(int i) {
    if (2 * (cells_ + 1) > keys_.size()) grow(2 * keys_.size());
    if (next_.size() <= std::size_t(i)) next_.resize(std::max<std::size_t>(i + 1, 2 * next_.size()), -1);
    const std::size_t slot = find_slot(CellGrid::key(grid_.cell_of(positions_[i])));
    if (head_[slot] < 0) ++cells_;
    next_[i] = head_[slot];
    head_[slot] = i;
  }

  // Calls visit(j) for every element j in the 27 cells around `p` (i.e. at least all within one
  // cell width of it), p's own element included if it is one.
  template <class F>
  void for_each_near(const glm::dvec3& p, F&& visit) const {
    if (keys_.empty()) return;
    grid_.for_each_key_around(p, [&](std::uint64_t key) {
      for (int j = head_[find_slot(key)]; j >= 0; j = next_[j]) visit(j);
    });
  }

private:
  // Open addressing with linear probing: a cell's points form a list through next_, so that the
  // hash holds three flat arrays and no allocation per cell (the per-cell vectors of a
  // std::unordered_map cost a third of a 1M-element run's time in lookups).
  static constexpr std::uint64_t kEmpty = ~std::uint64_t(0);  // CellGrid keys use 63 bits
  std::size_t find_slot(std::uint64_t key) const {
    // Four cells in a row along z share a hash and take neighbouring slots, so a query's 27 cells
    // read nine runs of memory rather than 27 scattered slots. The hash is the product's high
    // bits, which depend on every bit of the rest of the key (its low bits would see only the
    // low bits of the key: z and y, crowding a flat part's rows of cells into one slot).
    const std::uint64_t run = key & 3;
    std::size_t slot = (std::size_t(((key ^ run) * 0x9e3779b97f4a7c15ull) >> shift_) + run) & (keys_.size() - 1);
    while (keys_[slot] != key && keys_[slot] != kEmpty) slot = (slot + 1) & (keys_.size() - 1);
    return slot;
  }
  std::size_t find_slot(std::uint64_t key) {
    std::size_t slot = std::as_const(*this).find_slot(key);
    keys_[slot] = key;
    return slot;
  }
  void grow(std::size_t wanted) {
    std::size_t size = 64;
    int bits = 6;
    while (size < wanted) size *= 2, ++bits;
    if (size <= keys_.size()) return;
    shift_ = 64 - bits;
    std::vector<std::uint64_t> keys = std::move(keys_);
    std::vector<int> heads = std::move(head_);
    keys_.assign(size, kEmpty);
    head_.assign(size, -1);
    for (std::size_t s = 0; s < keys.size(); ++s)
      if (keys[s] != kEmpty) head_[find_slot(keys[s])] = heads[s];
  }

  const std::vector<glm::dvec3>& positions_;
  CellGrid grid_;
  std::vector<std::uint64_t> keys_;  // cell key per slot, kEmpty when free
  std::vector<int> head_;            // last point inserted in the slot's cell, -1 when none
  std::vector<int> next_;            // the point inserted before it in the same cell
  std::size_t cells_ = 0;
  int shift_ = 58;                   // 64 - log2(table size)
};

}  // namespace paver
