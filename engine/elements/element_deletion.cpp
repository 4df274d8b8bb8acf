#include "elements/element_deletion.h"

#include <glm/geometric.hpp>

#include <limits>
#include <unordered_map>

namespace paver {

int delete_elements(Elements& elements, const ElementEdits& edits, int first_refill_id) {
  if (edits.deleted.empty()) return 0;
  std::unordered_map<int, std::size_t> index_of;
  for (std::size_t i = 0; i < elements.size(); ++i) index_of.emplace(elements.id[i], i);
  std::vector<std::uint8_t> remove(elements.size(), 0);
  int missed = 0;
  for (const DeletedElement& d : edits.deleted) {
    const bool refilled = d.id >= first_refill_id && d.id < kFirstAddedId;
    std::size_t found = elements.size();
    if (!refilled) {
      if (const auto it = index_of.find(d.id); it != index_of.end()) found = it->second;
    } else {
      double nearest = std::numeric_limits<double>::infinity();
      for (std::size_t i = 0; i < elements.size(); ++i) {
        if (elements.id[i] < first_refill_id || elements.id[i] >= kFirstAddedId || remove[i]) continue;
        const double distance = glm::length(elements.uv[i] - d.uv);
        if (distance <= 0.5 * elements.diameter[i] && distance < nearest) nearest = distance, found = i;
      }
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
