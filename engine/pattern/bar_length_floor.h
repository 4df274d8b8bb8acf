#pragma once
// The shortest bar of a regular lattice on which the design's elements keep the contact rule:
// the vertex elements at its ends, its edge elements, and the edge elements of the bars beside it
// around a shared vertex (at the lattice's angle: 60 degrees for triangles, 120 for a honeycomb).
// The adaptive pattern packs its particles no nearer than this, so that its edge elements fit on
// every bar that is not squeezed by a defect.
#include "design/design.h"

namespace paver {

// In surface units; 0 when the design places no elements.
double bar_length_floor(const Design& design);

// How near two pattern particles may come (3D): the larger of the vertex elements' contact and
// the bar floor, aimed past it by kContactAim like every contact target.
double particle_contact_distance(const Design& design);

}  // namespace paver
