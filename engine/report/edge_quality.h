#pragma once
// What a jeweller judges a piece by, at its edges and holes (issue 40), as numbers the verdict can
// act on:
// - bare spots: places of the surface, inside the margin, where another stone of `spot_stone`
//   (0.8 d for pavé, or more for a pattern whose own holes are larger) would keep the gap to every
//   element; counted as the stones of that size that could be added there one by one;
// - rim metal: along every rim the design lays rows on, the distance from the rim less the margin
//   to the nearest element's girdle, in stone diameters d: a rim whose rows follow it keeps it
//   small everywhere, a clipped lattice leaves teeth.
// Measured on the surface in 3D, over all elements: the spots by find_bare_spots, the rims sampled
// every d / kRimSamplesPerStone.
#include "design/design.h"
#include "elements/bare_spots.h"
#include "elements/elements.h"
#include "map/surface_map.h"
#include "pattern/unit_cell.h"

#include <nlohmann/json_fwd.hpp>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <vector>

namespace paver {

inline constexpr double kUnevenRim = 0.3;       // rim metal p95 above 0.3 d: an uneven rim
inline constexpr int kRimSamplesPerStone = 10;

struct EdgeBasis {
  SpotBasis spots;        // d, the spot stone, gap and margin (elements/bare_spots.h); d 0 = not measured
  std::vector<int> rims;  // the boundary loops whose rim metal is measured (those with rows)
  bool pave = false;      // the regular pattern's stones touch (pattern/design_overlap.h): judged by its edges
};

struct EdgeQuality {
  bool measured = false;
  bool pave = false;             // the verdict and the choosers judge pave by these figures (report/verdict.h)
  double stone = 0, spot_stone = 0;
  long bare_spots = 0;
  double largest_fit = 0;        // the largest stone diameter that fits anywhere, surface units
  std::vector<BareSpot> spots;   // where, the largest first
  long rim_samples = 0;
  double rim_metal_p95 = 0;      // in stone diameters d; 0 when no rim is measured
  double rim_metal_max = 0;
};

// report.json lists this many spots at the most (the widest first); the count is all of them.
inline constexpr std::size_t kSpotsListed = 100;

// Inputs: the map the elements' uv are on, the elements, the basis. Output: the figures above.
EdgeQuality measure_edges(const SurfaceMap& map, const Elements& elements, const EdgeBasis& basis);

// The basis of a design at the spacing of its cell: d is the V-element's diameter (else the
// largest E-element's); a spot fits 0.8 d, or 1.25 times the widest stone that fits between the
// elements of the regular pattern itself (the centre of a honeycomb's hexagon), whichever is
// larger; the rims measured are those the design lays rows along (elements/rim_rows.h).
EdgeBasis edge_basis(const SurfaceMap& map, const UnitCell& cell, const ElementsDesign& elements);

// The widest stone that fits between the elements of the regular pattern of `cell` (with the
// design's elements), keeping the gap: in pattern-plane units.
double widest_regular_hole(const UnitCell& cell, const ElementsDesign& elements);

// report.json's quality "edges": null when not measured.
nlohmann::json to_json(const EdgeQuality& quality);

}  // namespace paver
