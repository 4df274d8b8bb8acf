#include "map/cut_axis.h"

namespace paver {

std::string_view cut_axis_name(CutAxis axis) {
  switch (axis) {
    case CutAxis::Auto: return "auto";
    case CutAxis::X: return "x";
    case CutAxis::Y: return "y";
    case CutAxis::Z: return "z";
  }
  return "?";
}

std::optional<CutAxis> cut_axis_from_name(std::string_view name) {
  for (CutAxis a : {CutAxis::Auto, CutAxis::X, CutAxis::Y, CutAxis::Z})
    if (name == cut_axis_name(a)) return a;
  return std::nullopt;
}

}  // namespace paver
