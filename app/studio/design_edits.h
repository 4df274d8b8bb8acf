#pragma once
// Edits of a design that keep it consistent, shared by the panels and the script: a new
// tessellation drops what named the old cell's edges; an edge operator is only added when the
// unit cell can take it.
#include "design/design.h"
#include "pattern/unit_cell.h"

namespace paver::studio {

// The design with another tessellation. The operators and the E-elements' cell edges name
// edges of the old cell, so they are cleared when the tessellation really changes.
Design with_tessellation(Design design, Tessellation tessellation);

// The design with `op` appended to its operators. Throws InputError (from the unit cell: no such
// edge, edge already there, ...) when the cell cannot take it.
Design with_operator(Design design, const EdgeOperator& op);

// The design without operator `index`. Throws InputError when a later operator needs it.
Design without_operator(Design design, int index);

// The design's unit cell at D = 1 (operators and bracing applied), for drawing and for listing
// the edges E-elements can sit on.
UnitCell design_cell_shape(const PatternDesign& pattern);

// Where the unit-cell editor centres its view: between the cell's vertices and its parallelogram,
// which no edge operator moves, so the view holds still under the cursor as edges are edited (it
// was centred on the edges, and re-centred after every flip, add or remove: the next click missed).
glm::dvec2 cell_view_centre(const UnitCell& cell);

}  // namespace paver::studio
