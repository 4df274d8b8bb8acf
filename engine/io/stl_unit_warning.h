#pragma once
// STL carries no unit and slicers read millimetres: a ring drawn in inches printed 0.9 mm across
// (a jeweller's trial). The CLI and the studio say the same words through this one function.
#include "design/design.h"

#include <string>
#include <vector>

namespace paver {

// The warning for STL files written in `units` ("" in millimetres or with no STL named), naming
// the files, the factor to scale by, and the 3MF files, which name their unit.
std::string stl_unit_warning(Units units, const std::vector<std::string>& stl_files);

}  // namespace paver
