#include "io/stl_unit_warning.h"

#include "core/number_text.h"

namespace paver {

std::string stl_unit_warning(Units units, const std::vector<std::string>& stl_files) {
  if (units == Units::Millimetre || stl_files.empty()) return {};
  std::string files;
  for (size_t i = 0; i < stl_files.size(); ++i)
    files += (i == 0 ? "" : i + 1 == stl_files.size() ? " and " : ", ") + stl_files[i];
  return files + (stl_files.size() == 1 ? " is" : " are") + " in " + std::string(enum_name(units)) +
         " (the surface's unit; STL has none) and slicers read millimetres: scale by " +
         number_text(millimetres_per_unit(units)) + " on import, or use the 3MF files, which name their unit";
}

}  // namespace paver
