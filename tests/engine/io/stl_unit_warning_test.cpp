#include "io/stl_unit_warning.h"

#include <gtest/gtest.h>

namespace paver {
namespace {

TEST(StlUnitWarning, MillimetresNeedNoWord) {
  EXPECT_EQ(stl_unit_warning(Units::Millimetre, {"elements.stl", "cut.stl"}), "");
  EXPECT_EQ(stl_unit_warning(Units::Inch, {}), "");  // no STL written
}

TEST(StlUnitWarning, AnotherUnitNamesTheFilesTheUnitAndTheFactor) {
  EXPECT_EQ(stl_unit_warning(Units::Inch, {"elements.stl"}),
            "elements.stl is in in (the surface's unit; STL has none) and slicers read millimetres: scale by 25.4 "
            "on import, or use the 3MF files, which name their unit");
  const std::string both = stl_unit_warning(Units::Metre, {"elements.stl", "cut.stl"});
  EXPECT_EQ(both.rfind("elements.stl and cut.stl are in m ", 0), 0u) << both;
  EXPECT_NE(both.find("scale by 1000 on import"), std::string::npos) << both;
  EXPECT_NE(stl_unit_warning(Units::Centimetre, {"cut.stl"}).find("cut.stl is in cm"), std::string::npos);
}

}  // namespace
}  // namespace paver
