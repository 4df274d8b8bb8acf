#include "elements/element_deletion.h"

#include "core/cell_grid.h"
#include "core/point_hash.h"

#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include <algorithm>
#include <limits>
#include <unordered_map>

namespace paver {

int delete_elements(Elements& elements, const ElementEdits& edits, int first_refill_id) {
  if (edits.deleted.empty()) return 0;
  std::unordered_map<int, std::size_t> index_of;
  for (std::size_t i = 0; i < elements.size(); ++i) index_of.emplace(elements.id[i], i);
  // Refilled elements are found by place (their ids change from run to run): in a hash of their
  // map points, so that a long list of deletions costs n log n, not n times every element.
  const auto is_refilled = [&](std::size_t i) { return elements.id[i] >= first_refill_id && elements.id[i] < kFirstAddedId; };
  std::vector<glm::dvec3> refilled_at(elements.size(), glm::dvec3(0));
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
  double reach = 0;
  for (std::size_t i = 0; i < elements.size(); ++i) {
    if (!is_refilled(i)) continue;
    refilled_at[i] = glm::dvec3(elements.uv[i], 0.0);
    lo = glm::min(lo, refilled_at[i]), hi = glm::max(hi, refilled_at[i]);
    reach = std::max(reach, 0.5 * elements.diameter[i]);
  }
  const bool any_refilled = lo.x <= hi.x;
  const CellGrid grid(any_refilled ? lo : glm::dvec3(0), any_refilled ? hi : glm::dvec3(1), std::max(reach, 1e-300));
  PointHash hash(refilled_at, grid, PointHash::Fill::None);
  for (std::size_t i = 0; i < elements.size(); ++i)
    if (is_refilled(i)) hash.insert(int(i));

  std::vector<std::uint8_t> remove(elements.size(), 0);
  int missed = 0;
  for (const DeletedElement& d : edits.deleted) {
    const bool refilled = d.id >= first_refill_id && d.id < kFirstAddedId;
    std::size_t found = elements.size();
    if (!refilled) {
      if (const auto it = index_of.find(d.id); it != index_of.end()) found = it->second;
    } else if (any_refilled) {
      const glm::dvec3 at(d.uv, 0.0);
      // Outside the refilled elements' box by more than their reach, nothing can be found (and
      // the cell indices of a point far away would overflow).
      if (glm::any(glm::lessThan(at, lo - reach)) || glm::any(glm::greaterThan(at, hi + reach))) {
        ++missed;
        continue;
      }
      double nearest = std::numeric_limits<double>::infinity();
      hash.for_each_near(at, [&](int j) {
        const auto i = std::size_t(j);
        if (remove[i]) return;
        const double distance = glm::length(elements.uv[i] - d.uv);
        // The nearest within its radius; of equals, the first (as a scan in order would find).
        if (distance <= 0.5 * elements.diameter[i] && (distance < nearest || (distance == nearest && i < found)))
          nearest = distance, found = i;
      });
    }
    if (found == elements.size())
      ++missed;
    else
      remove[found] = 1;
  }
  elements.erase_flagged(remove);
  return missed;
}

}  // namespace paver
