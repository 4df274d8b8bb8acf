#include "design/element_edits.h"

#include <algorithm>

namespace paver {

int ElementEdits::pinned_count() const {
  return int(std::count_if(moved.begin(), moved.end(), [](const MovedParticle& m) { return m.pinned; }));
}

int ElementEdits::next_added_id() const {
  int next = kFirstAddedId;
  for (const AddedElement& a : added) next = std::max(next, a.id + 1);
  // A deleted added element stays in `added` (deleted by id), so its id is never handed out again.
  for (const DeletedElement& d : deleted) next = std::max(next, d.id >= kFirstAddedId ? d.id + 1 : next);
  return next;
}

}  // namespace paver
