#pragma once
// Stable element ids: an element keeps its id across re-optimization and across the designer's
// edits of other elements, so that the studio, its script, design.json "edits" and placements.csv
// name the same stone. An id follows from where the element comes from, never from its position
// in the list (which collision resolution and the boundary change):
//   vertex element of pattern point p ............ p                     (0 <= p < P, the design's points)
//   edge element on pattern edge e ............... P + e
//   boundary filling on crossing edge c .......... P + E + c
//   face element in pattern face f ............... P + E + C + f         (F = 0 faces without F-elements)
//   refill and rim-row elements, in order ........ P + E + C + F + k     (placed anew by every run)
//   the designer's added elements ................ their own, from kFirstAddedId (design/element_edits.h)
//   beads ........................................ after the largest of the above below kFirstAddedId
// A retired or deleted element's id is not given to another.
#include "elements/elements.h"
#include "design/element_edits.h"
#include "pattern/pattern.h"

namespace paver {

// The first id of the elements the refill and the rim rows add (P + E + C + F above).
int first_refill_id(const Pattern& pattern);

// Names every element of `elements` (placed on `pattern`, whose last points are `added`, in order).
void number_elements(Elements& elements, const Pattern& pattern, const std::vector<AddedElement>& added);

// Names the beads after the stones' ids.
void number_beads(Elements& beads, const Elements& stones);

}  // namespace paver
