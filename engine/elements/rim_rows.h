#pragma once
// Rim rows (issue 12, "the user can ask for a row of elements that follows a rim"): a hole's edge
// trimmed through a lattice looks cut, not designed. On request (elements.rim_rows: "holes" or
// "all"), each chosen rim gets a row of V-elements that follows it: centres on the curve a radius
// plus the margin inside the rim, spaced evenly along it, as many as close the loop with the
// contact rule (and the gap) between neighbours. The pattern's elements that the row would touch
// make way; the bare regions' refill then packs against the row. A closed surface's seams are not
// rims and get none.
#include "design/design.h"
#include "elements/elements.h"
#include "map/surface_map.h"

namespace paver {

struct RimRowReport {
  int loops = 0;      // rims that got a row
  int placed = 0;     // elements along them
  int made_way = 0;   // pattern elements removed because the row would touch them
  double milliseconds = 0;
};

// The rows a design's `rim_rows` lays: auto is every rim where `rows_for_pave` (tri pave, which a
// jeweller judges at its rims: the caller's rule, pipeline/pave_once.cpp), none otherwise; the
// others as they are.
RimRows concrete_rim_rows(RimRows rows, bool rows_for_pave);

// Which of the map's loops are rims the design asks a row for: none, the holes (every loop but
// the outer, the longest), or all. A band whose rims are alike (a ring) has no hole: "holes" lines
// none of its edges there, where it once lined one and left the ring lopsided.
std::vector<int> rim_row_loops(const SurfaceMap& map, RimRows rows);

// A band whose two rims are within kAlikeRims of each other's length: a ring's or a bangle's two
// edges, not an outer edge and a hole (a pendant pierced once has a hole far shorter than its rim).
inline constexpr double kAlikeRims = 1.25;
bool band_rims_alike(const SurfaceMap& map);

// Inputs: the map the pavement's uv live in, its elements, the design's elements (the rims asked
// for, the V size and shape, gap, margin) at spacing D. Output: the rows added to `elements`
// (source -1, the design's vertex spec) and the elements they would touch removed. Does nothing
// for RimRows::None, on an atlas, or when the design has no V-elements.
RimRowReport place_rim_rows(const SurfaceMap& map, Elements& elements, const ElementsDesign& spec, double spacing);

}  // namespace paver
