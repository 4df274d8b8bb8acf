#pragma once
// Beads (shared prongs): in pavé a setter raises small beads of metal between the stones, each
// pushed over the girdles of the stones around it, and every stone is held by at least three.
//
// Where three stones are in contact (every two no farther apart than their radii plus the gap
// plus kBeadContactSlack of the smaller diameter), one bead goes in their gap, at the point of
// the surface under the three centres' middle (lifted from their map coordinates). A stone that
// these leave with fewer than kBeadsPerStone holders (a rim stone, a grid's or a honeycomb's) gets
// beads of its own around its girdle, each where it keeps off the other stones' tables, clear of
// the other beads and on the metal, the one farthest in angle from its holders first.
//
// Sizes: a bead is at least `min_diameter` (castable: 0.5 mm by default), reaches `over` over the
// girdle of every stone it holds, and is `scale` times the largest sphere that fits between its
// stones if that is larger. It may reach over a stone's girdle as far as the stone's table and no
// farther (kTableShare), keeps the gap from every other bead, and stays on the surface (inside
// its rims, not its margin: a bead is metal). Beads are not in the pavement's elements, the contact
// rule or the bill of stones; they are exported with the stones (kind Bead) and joined to the
// metal by the cut.
#include "design/design.h"
#include "elements/elements.h"
#include "map/surface_map.h"

#include <nlohmann/json_fwd.hpp>

#include <optional>
#include <string>
#include <vector>

namespace paver {

inline constexpr double kBeadContactSlack = 0.15;
inline constexpr int kBeadsPerStone = 3;
// A bead holds a stone when its centre is within the stone's radius plus its own plus this share
// of the stone's diameter.
inline constexpr double kBeadHoldSlack = 0.05;
// And its holders must surround it: no angle around it wider than this without one (three beads
// on one side let it tip out of its seat).
inline constexpr double kWidestOpenDeg = 180;
// How far a bead may reach into a stone's footprint: to its table's edge, as a share of its
// diameter (a round brilliant's girdle radius 0.5 less its table radius 0.28).
inline constexpr double kTableShare = 0.22;
// Beads finer than this (mm) are said to be: casting and wax printing fill them unreliably
// (a cast bead is about 0.5-0.6 mm; elements.beads.min_diameter is 0.5 by default).
inline constexpr double kFinestCastBeadMm = 0.2;

// Elements of kind Bead, shape Sphere; none unless design.beads.enabled. Every length of `design`
// in surface units (the pass converts the bead sizes from mm).
Elements place_beads(const SurfaceMap& map, const Elements& stones, const ElementsDesign& design);

// How the beads hold the stones, counted apart from how they were placed: holders per stone
// (kBeadHoldSlack), the widest angle around a stone with no holder, and the clearances.
struct BeadHold {
  std::vector<int> holders;                  // #stones
  std::vector<double> widest_open_deg;       // #stones: 360 with no holder
  std::vector<int> underheld;                // stones with fewer than kBeadsPerStone holders, or open wider than kWidestOpenDeg
  double least_bead_clearance = 0;           // between two beads' footprints (infinity with < 2)
  int over_tables = 0;                       // beads reaching past a stone's table edge
};
BeadHold measure_bead_hold(const Elements& stones, const Elements& beads);

// report.json's `beads`: the design's bead keys, count, sizes in mm and the hold above.
nlohmann::json bead_hold_json(const Elements& stones, const Elements& beads, const ElementsDesign& design, Units units);

// "12 of 610 beads are under 0.2 mm (the smallest 0.03 mm): ..." when any bead is finer than
// kFinestCastBeadMm; nothing otherwise. `units` is the design's, for millimetres.
std::optional<std::string> fine_beads_warning(const Elements& beads, Units units);

// "14 stones are held by fewer than 3 beads around them (ids 3, 17, ...): ..." when any is; nothing otherwise.
std::optional<std::string> underheld_stones_warning(const Elements& stones, const BeadHold& hold);

}  // namespace paver
