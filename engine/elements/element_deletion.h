#pragma once
// The designer's deletions (design.edits.deleted), applied to the final elements: a deleted stone
// leaves its place empty (no refill runs after it), and its neighbours stay where they are.
#include "design/element_edits.h"
#include "elements/elements.h"

namespace paver {

// Removes the deleted elements (numbered: elements/element_ids.h) from `elements`: a pattern or an
// added element by its id, one the refill added by its position (the refill places anew after any
// edit upstream): the nearest refill element whose footprint covers the recorded point. Returns
// how many deletions found no element.
int delete_elements(Elements& elements, const ElementEdits& edits, int first_refill_id);

}  // namespace paver
