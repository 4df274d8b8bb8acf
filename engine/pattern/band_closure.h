#pragma once
// Closing a lattice around a band (issue 12, "Bands: seamless"): on a map that wraps every
// T = (period, 0), the lattice is turned so that T is a lattice vector and its spacing changed by
// the least amount that makes a whole number of elements go around: "D 0.630 -> 0.628: 90
// elements close the band".
#include "design/design.h"
#include "map/surface_map.h"
#include "pattern/unit_cell.h"

#include <glm/vec2.hpp>

#include <cstddef>
#include <string>

namespace paver {

struct BandClosure {
  double spacing_before = 0;  // the design's D
  double spacing = 0;         // D after closing
  int around = 0;             // lattice steps (elements in a row) once around the band
  glm::ivec2 step{1, 0};      // the lattice vector that repeats around, in cells (a1, a2)
  double rotation_deg = 0;    // the placement rotation that lines it up with the band
  bool rows_across = false;   // the rows run across the band (else along it)
  bool stones_kept = false;   // gem elements kept their diameter; the gap took the change in D
  double gap_asked = 0;       // elements.gap, surface units: the lattice's gap is this plus the change in D
  double lattice_gap() const { return gap_asked + spacing - spacing_before; }
  // band_rows auto: the elements each way laid out (before optimization) at its best shift across
  // the band, and kept once paved (0 when a band too large to pave twice took the way that laid
  // out more); all 0 when the design named the rows.
  std::size_t laid_out_across = 0, laid_out_along = 0;
  std::size_t kept_across = 0, kept_along = 0;
};

// The closure of `cell` (at the design's spacing) on `map` (which wraps) under `placement`
// (its scale counts; its rotation is replaced; band_rows along or across, not auto, which the
// caller resolves by trying both): the nearest whole number of steps, or with
// `never_closer` the largest that does not bring the elements closer (stones, or a design at its
// gap's limit): an InputError when fewer than three such steps go around.
BandClosure close_band(const SurfaceMap& map, const UnitCell& cell, const Placement& placement,
                       bool never_closer = false);

// A band closed with its rows one way: the design at the closed D with the band's rotation.
struct ClosedBand {
  Design design;
  BandClosure closure;
};

// Inputs: the band's seamless map (it wraps), the design at its own spacing, the rows' way (along
// or across). Output: the design closed around the band: stones (gem elements) keep their
// diameter and the gap takes the change, so D only grows; other elements are sized with D, one
// step fewer where a closer D would break the design's gap. InputError when fewer than three
// steps go around.
ClosedBand close_band_design(const SurfaceMap& map, Design design, BandRows rows);

// "D 0.630 -> 0.628: 90 elements close the band (rows along it)", and "; the stones keep their
// size, the gap takes the change: 0.1 -> 0.128 (+1.3% of D)" when they did.
std::string describe_band_closure(const BandClosure& closure);
// "; rows auto: along kept 13 elements, across 7" for band_rows auto; "" when the rows were named.
std::string band_rows_choice(const BandClosure& closure);

}  // namespace paver
