#pragma once
// Post-processing (section 5.4). Filling: lattice edges that cross the map's boundary are split at
// the crossing and E-elements are placed on the inside part at their t. Eliminating: every
// element whose centre is nearer the surface boundary (in 3D) than its radius plus the design's
// margin (elements.margin, a jeweller's edge distance; 0 in the paper) is removed.
#include "design/design.h"
#include "elements/element_placement.h"
#include "elements/elements.h"
#include "pattern/grade_field.h"
#include "pattern/pattern.h"
#include "map/surface_map.h"

#include <cstdint>
#include <vector>

namespace paver {

// Appends the filling E-elements to `elements`; returns how many were added. `points` are the
// optimised particle positions; the outside end of a crossing edge moves with its inside end.
int fill_boundary_edges(const SurfaceMap& map, const Pattern& pattern, const std::vector<glm::dvec2>& points,
                        const ElementsDesign& design, double spacing, Elements& elements,
                        const std::vector<std::uint8_t>* retired = nullptr);

// 3D distance from each element centre to the surface's boundary polyline, capped at the largest
// element diameter plus `reach` (only near elements matter: crossing tests with a margin of up to
// `reach`, the interior of the valence share; farther ones get the cap).
std::vector<double> distances_to_boundary(const SurfaceMap& map, const Elements& elements, double reach = 0);

// Whether an element `distance` from the boundary keeps the margin: its footprint (radius) and the
// margin both fit. The one rule for elimination, refill and the report.
inline bool keeps_margin(double distance, double diameter, double margin) {
  return distance >= 0.5 * diameter + margin;
}

// Removes the elements that cross the boundary or its margin; returns how many.
int eliminate_boundary_elements(const SurfaceMap& map, Elements& elements, double margin = 0);

// Inputs: the map, the pattern and its particle positions `points` (#P), the design's elements at
// spacing D; `anchor` as place_elements takes it; `retired` (optional, #P) the particles the
// optimizer retired. Output: the elements placed, then (with `postprocess`, section 5.4) filled at
// and eliminated near the boundary with its margin, and how many of each. Graded stones
// (`grade`) take their sizes before the boundary judges them.
struct PlacedElements {
  Elements elements;
  int filled = 0, eliminated = 0;
};
PlacedElements place_all_elements(const SurfaceMap& map, const Pattern& pattern, const std::vector<glm::dvec2>& points,
                                  const ElementsDesign& design, double spacing, EdgeAnchor anchor, bool postprocess,
                                  const std::vector<std::uint8_t>* retired = nullptr,
                                  const GradeField* grade = nullptr);

}  // namespace paver
