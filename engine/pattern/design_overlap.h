#pragma once
// The paper does not allow elements that intersect in the design itself (section 6.3,
// "Extension"): checked on the regular lattice, before any surface is involved. Designs that
// want overlapping elements (the paper's Fig. 15) set elements.allow_overlap.
#include "design/design.h"
#include "pattern/unit_cell.h"

namespace paver {

// Throws InputError naming the two elements and the fix when two elements of the regular
// pattern collide by the contact rule (core/contact_rule.h) with `gap` (surface units at this
// spacing).
void check_design_overlaps(const UnitCell& cell, const ElementsDesign& elements, double spacing, double gap = 0);

}  // namespace paver
