#pragma once
// From a surface map and a design to elements (sections 4.1 and 4.2): the unit cell with the
// design's operators, the trimmed pattern, and the elements lifted to the surface. The CLI and the
// editor both call make_pavement; the map is built once per surface (build_surface_map), the
// pavement again on every design change.
#include "paver/design.h"
#include "paver/elements.h"
#include "paver/pattern.h"
#include "paver/surface_map.h"
#include "paver/unit_cell.h"

#include <string>
#include <utility>
#include <vector>

namespace paver {

// Wall-clock milliseconds per named stage, in pipeline order.
using StageTimings = std::vector<std::pair<std::string, double>>;

struct Pavement {
  Design design;                     // as used: spacing resolved
  UnitCell cell;                     // after operators and bracing
  Pattern pattern;                   // trimmed pattern S^
  std::vector<glm::dvec2> points;    // particle positions (the pattern's, until optimised)
  Elements elements;
  StageTimings timings;
};

// Unit cell of the design: tessellation at D, operators in order, bracing edges if asked.
// Throws InputError naming the operator ("pattern.operators[1]: ...") when one fails.
UnitCell make_design_cell(const PatternDesign& pattern);

// Resolves spacing 0 to the surface's default and checks design references against the unit
// cell (E-element cell_edges), then builds pattern and elements.
Pavement make_pavement(const SurfaceMap& map, Design design);

}  // namespace paver
