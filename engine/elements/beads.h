#pragma once
// Beads (shared prongs): in pavé a setter raises a small bead of metal in the gap between three
// stones, and it holds all three. One bead goes where three stones are in contact: every two of
// them no farther apart than their radii plus the gap plus kBeadContactSlack of the smaller
// diameter. It sits at the point of the surface under the three centres' middle (lifted from
// their map coordinates), as large as `scale` times the largest sphere that fits there between
// their footprints. Beads are metal, not stones: they are not in the pavement's elements, the
// contact rule or the bill of stones; they are exported with the stones (kind Bead) and counted.
// Triangle lattices give them; grid and hex have no three stones in mutual contact.
#include "design/design.h"
#include "elements/elements.h"
#include "map/surface_map.h"

#include <optional>
#include <string>

namespace paver {

inline constexpr double kBeadContactSlack = 0.15;
// Beads finer than this (mm) are said to be: our judgement of the finest bead that casting or wax
// printing holds and a setter can use, not a standard (the pendant's 1.5 mm stones with a 0.1 mm
// gap get beads of 0.25-0.36 mm; a gem design's edge stones left 0.03 mm).
inline constexpr double kFinestCastBeadMm = 0.2;

// Elements of kind Bead, shape Sphere; none unless design.beads.enabled. A bead whose footprint
// would leave the surface or its margin is left out.
Elements place_beads(const SurfaceMap& map, const Elements& stones, const ElementsDesign& design);

// "12 of 610 beads are under 0.2 mm (the smallest 0.03 mm): ..." when any bead is finer than
// kFinestCastBeadMm; nothing otherwise. `units` is the design's, for millimetres.
std::optional<std::string> fine_beads_warning(const Elements& beads, Units units);

}  // namespace paver
