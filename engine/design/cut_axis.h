#pragma once
// Which plane a closed surface (a bead, a figurine) is cut across to be laid flat in charts
// (map/surface_charts.h): its normal is the surface's longest axis, or a given one. A design keeps
// it (placement.cut_axis), so that a saved design repeats the same charts.
#include "core/enum_names.h"

namespace paver {

enum class CutAxis { Auto, X, Y, Z };

PAVER_ENUM_NAMES(CutAxis, {CutAxis::Auto, "auto"}, {CutAxis::X, "x"}, {CutAxis::Y, "y"}, {CutAxis::Z, "z"});

}  // namespace paver
