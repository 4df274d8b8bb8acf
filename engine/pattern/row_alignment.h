#pragma once
// Rows along a world axis (placement.align): the map's orientation is whatever the map made of
// the surface (LSCM pins two far vertices; a curved facade's grid ran at 26.6 degrees to the
// floor). The rotation that lays the lattice's first direction a1 along the axis, as the axis
// projects onto the surface, averaged over the surface by area.
#include "map/surface_map.h"
#include "pattern/placement.h"
#include "pattern/unit_cell.h"

#include <optional>

namespace paver {

struct RowAlignment {
  AlignAxis axis = AlignAxis::None;
  double rotation_deg = 0;  // added to placement.rotation_deg
  // How well one rotation serves the whole surface: the area-weighted spread of the axis's
  // direction on the map, 0 (the same everywhere) to 1 (no preferred direction).
  double spread = 0;
};

// The rotation for `axis` on `map`, or nothing when the axis is (nearly) normal to the surface
// everywhere (no direction to follow): a wall cannot have rows along its own normal.
std::optional<RowAlignment> align_rows(const SurfaceMap& map, const UnitCell& cell, AlignAxis axis);

}  // namespace paver
