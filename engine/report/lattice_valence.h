#pragma once
// How many lattice neighbours each V-element has, measured on the final elements alone (not on the
// solver's pattern), for the report's regular-valence share:
// - triangle lattices: its degree in the surface-Delaunay triangulation of the V-elements (the
//   coordination number of packings; 5 and 7 are the point defects);
// - square and hexagonal lattices, whose Delaunay triangulations are degenerate: the V-elements
//   within kValenceShell times its nearest one's distance (element_proximity.h).
#include "elements/elements.h"

#include <vector>

namespace paver {

inline constexpr double kValenceShell = 1.25;  // between the first ring (1) and the second (sqrt 2)

// Per element: its valence, -1 for E-elements. `regular_valence` is the lattice's (6, 4 or 3);
// `spacing` is D (triangles longer than 2.5 D, across a concave boundary, are not edges).
// `period` > 0: the elements' uv repeat every (period, 0) (a band's seamless map), and neighbours
// across the seam count.
std::vector<int> lattice_valences(const Elements& elements, int regular_valence, double spacing, double period = 0);

}  // namespace paver
