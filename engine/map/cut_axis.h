#pragma once
// Which plane a closed surface (a bead, a figurine) is cut across to be laid flat in charts
// (map/surface_charts.h): its normal is the surface's longest axis, or a given one. A design keeps
// it (placement.cut_axis), so that a saved design repeats the same charts.
#include <optional>
#include <string_view>

namespace paver {

enum class CutAxis { Auto, X, Y, Z };
std::string_view cut_axis_name(CutAxis axis);  // "auto", "x", "y", "z"
std::optional<CutAxis> cut_axis_from_name(std::string_view name);

}  // namespace paver
