#pragma once
// The design's unit cell (section 4.1) and the checks a design must pass before any surface is
// read: its operators apply, its E-elements name cell edges that exist, its elements do not
// overlap in the regular lattice, and its topology takes its edits and guidance field.
#include "design/design.h"
#include "pattern/unit_cell.h"

namespace paver {

// The tessellation's own cell at D, or the designer's drawn one (tessellation "cell"), before any
// operator. Throws DesignError naming pattern.cell's vertex or edge when the drawn one is not a
// tessellation.
UnitCell make_base_cell(const PatternDesign& pattern);

// Inputs: the pattern's tessellation, spacing D, operators and bracing.
// Output: the unit cell at D with the operators applied in order and the bracing edges if asked.
// Throws DesignError naming the operator ("pattern.operators[1]: ...") when one fails.
UnitCell make_design_cell(const PatternDesign& pattern);

// Element ids name the elements of one pattern, and only the lattice's solver holds particles or
// follows a painted field: refused (DesignError) when the topology cannot take them.
void check_edits_topology(const Design& design);

// The design's checks that need no surface (above). Scale-free, so a design whose spacing is still
// 0 (derived later) is checked at D = 1; a gap (surface units) is checked once the spacing is
// known. Returns the design's cell at its spacing (at D = 1 while it is 0). Throws DesignError
// naming the key.
UnitCell check_design_cell(const Design& design);

}  // namespace paver
