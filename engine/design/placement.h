#pragma once
// How the 2D map M^ sits under the pattern U^ (section 4.2): the map is scaled, rotated and then
// translated into the pattern plane. Pattern point p and map point q relate by
//   p = R(rotation) * (scale * q) + offset.
#include "design/cut_axis.h"

#include <glm/vec2.hpp>

namespace paver {

// On a band paved seamlessly, which way the lattice's rows run: along the band (around it) or
// across it (rim to rim), or auto: both tried and the better pavement kept (pipeline/choices.h).
// Its rotation is then the band's, not `rotation_deg`.
enum class BandRows { Along, Across, Auto };
PAVER_ENUM_NAMES(BandRows, {BandRows::Along, "along"}, {BandRows::Across, "across"}, {BandRows::Auto, "auto"});

// Rows along a world axis (pattern/row_alignment.h): the rotation is then the axis's, plus
// rotation_deg. None: the map's own orientation.
enum class AlignAxis { None, X, Y, Z };
// "none" last: the choices read "x, y, z or none".
PAVER_ENUM_NAMES(AlignAxis, {AlignAxis::X, "x"}, {AlignAxis::Y, "y"}, {AlignAxis::Z, "z"}, {AlignAxis::None, "none"});

struct Placement {
  glm::dvec2 offset{0, 0};              // pattern-plane units (same as D); default 0
  double rotation_deg = 0;              // degrees; the map is turned counter-clockwise into the pattern, so the lattice
                                        // seen on the map turns clockwise (docs/design_file.md); default 0
  double scale = 1;                     // > 0; default 1 (the map keeps the surface's area)
  BandRows band_rows = BandRows::Auto;  // default "auto" (docs/holes_and_bands.md says why)
  CutAxis cut_axis = CutAxis::Auto;     // a closed surface's charts: cut across this axis (paver run --cut)
  AlignAxis align = AlignAxis::None;    // rows along this world axis; not on a seamless band (its rows close)
  bool fit_offset = false;              // shift `offset` within one cell for the most elements (pipeline/offset_fit.h)

  glm::dvec2 map_to_pattern(glm::dvec2 q) const;
  glm::dvec2 pattern_to_map(glm::dvec2 p) const;
};

}  // namespace paver
