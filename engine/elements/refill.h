#pragma once
// Refill: bare regions get elements. Where the pattern tore, or elements were eliminated at the
// boundary or removed as a last resort, a pavement has holes a whole element would fit in. Grown
// outwards from every element in waves: candidates in 12 tangent directions, put on the surface
// through the map, kept when they stay inside the boundary, keep the contact rule (with the gap)
// with every element, and lie no closer to any V-element than the design's own density allows: the
// spacing of a triangle packing with the design's area per V-element, times eq. 5's factor
// (1 + c + m * normalised |H|) there. So a design with margins keeps its margins and a honeycomb
// is not packed denser than a honeycomb. Linear in the elements (a spatial hash; each element
// seeds once). Beyond the paper (its future work on combinatorial singularities); the added
// elements are V-elements of the design's vertex spec, in a close packing of their own.
#include "design/design.h"
#include "elements/elements.h"
#include "map/surface_map.h"

#include <atomic>

namespace paver {

struct RefillReport {
  int added = 0;
  int on_seams = 0;  // of `added`: straddling a closed surface's chart seams (refill_seams)
  int waves = 0;
  double milliseconds = 0;
};

// How dense a refill may be: no closer to any V-element than a triangle packing with the regular
// pattern's area per V-element (QualityBasis's area per element over its V share), times eq. 5's
// growth 1 + c + m |H| at the curvature there (the design's solver.c and solver.m).
struct RefillDensity {
  double area_per_vertex_element = 0;
  double c = 0, m = 0;
};

// Inputs: the map, the elements so far, the design's elements (V size, shape, gap, margin) at
// spacing D (> 0), the density rule. Output: the added elements appended to `elements` (their
// source is -1: no pattern point carries them), and how many. Does nothing when the design has no
// V-elements or no element exists to grow from.
RefillReport refill_bare_regions(const SurfaceMap& map, Elements& elements, const ElementsDesign& spec, double spacing,
                                 const RefillDensity& density, const std::atomic<bool>* stop = nullptr);

// A closed surface's atlas (map/surface_charts.h): each chart's elements keep off its seams, so a
// strip about two element radii wide runs bare along every seam, though the seam is no edge of the
// real surface. This walks every seam and adds elements across it wherever one keeps the contact
// rule and the density rule above with every element, in 3D, over both charts: its centre on the
// seam or up to half a diameter into either chart, the nearest to the seam that fits, greedily
// along the seam. Adds to `report` (added, on_seams). Does nothing on a map that is no atlas.
void refill_seams(const SurfaceMap& map, Elements& elements, const ElementsDesign& spec, double spacing,
                  const RefillDensity& density, RefillReport& report);

}  // namespace paver
