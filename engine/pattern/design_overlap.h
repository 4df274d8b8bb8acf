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

// Pave: the regular pattern's stones touch. Every V-element of it lies within kTouchingShare of
// its diameter of its nearest neighbour (by the contact rule with `gap`, surface units at the
// cell's spacing): a jeweller's pave, where a place one more stone fits is a hole to the eye and a
// rim without a row shows teeth (issue 40). A pattern spaced wider (discs on a facade, spheres at
// 0.8 D) is judged by its own spacing, not by its spots.
inline constexpr double kTouchingShare = 0.05;
bool stones_touch(const UnitCell& cell, const ElementsDesign& design, double gap);

}  // namespace paver
