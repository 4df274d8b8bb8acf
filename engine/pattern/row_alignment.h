#pragma once
// Rows along a world axis (placement.align): the map's orientation is whatever the map made of
// the surface (LSCM pins two far vertices; a curved facade's grid ran at 26.6 degrees to the
// floor). The rotation that lays the lattice's first direction a1 along the axis, as the axis
// projects onto the surface, averaged over the surface by area.
#include "map/surface_map.h"
#include "design/placement.h"
#include "pattern/unit_cell.h"

#include <optional>

namespace paver {

struct RowAlignment {
  AlignAxis axis = AlignAxis::None;
  double rotation_deg = 0;  // added to placement.rotation_deg
  // How well one rotation serves the whole surface: the spread (circular standard deviation,
  // area-weighted) of the axis's direction on the map, in degrees; 0 where it is the same
  // everywhere (a facade), about 20 on a vase wrapped 270 degrees around the other axis.
  double spread_deg = 0;
  // How steeply the axis meets the surface, on average: 0 when it lies in the surface, 90 along
  // the normal (rows along it then follow only the surface's slope).
  double axis_to_surface_deg = 0;
};

// Above these a run warns: the rows follow the axis poorly (pipeline/run_pipeline.cpp).
inline constexpr double kAlignSpreadWarnDeg = 15;
inline constexpr double kAlignSteepWarnDeg = 60;

// The rotation for `axis` on `map`, or nothing when the axis is (nearly) normal to the surface
// everywhere (no direction to follow): a wall cannot have rows along its own normal.
std::optional<RowAlignment> align_rows(const SurfaceMap& map, const UnitCell& cell, AlignAxis axis);

}  // namespace paver
