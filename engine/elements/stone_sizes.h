#pragma once
// Stocked sizes (issue 43): melee is sold in sieve sizes (1.0, 1.1, 1.2, 1.3, 1.35, 1.4 ... mm), and
// a setter fills what the main size leaves with the largest smaller size that fits. After the
// pass, for each of the design's fill sizes, largest first, every place of the surface where a
// stone of that size keeps the gap to every element and the margin to the rims gets one: the
// places found as bare spots are (elements/bare_spots.h, on the surface in 3D, all elements), the
// tightest taken first so that the new stones pack against their neighbours, and searched again
// until none is left. Nothing moves: the pass's stones stay where they are.
#include "design/design.h"
#include "elements/elements.h"
#include "map/surface_map.h"

#include <atomic>
#include <vector>

namespace paver {

struct SizeFill {
  struct Size {
    double diameter = 0;  // surface units
    int added = 0;
  };
  std::vector<Size> sizes;  // the sizes used, largest first
  int rounds = 0;           // searches made, over all sizes
  double milliseconds = 0;
  int added() const;
};

// Inputs: the map the elements' uv are on, the elements (appended to: V-elements of the design's
// vertex shape, source -1), the design's elements (fill_sizes, gap, margin, vertex shape) and the
// main stone's diameter; sizes not smaller than it, or under kLeastFillShare of it, are not used. Stops between searches when
// `stop` becomes true.
SizeFill fill_with_smaller_sizes(const SurfaceMap& map, Elements& elements, const ElementsDesign& spec,
                                 double main_stone, const std::atomic<bool>* stop = nullptr);

}  // namespace paver
