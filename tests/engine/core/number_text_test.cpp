// Tests for engine/core/number_text.h: figures for people are grouped and rounded, never in
// scientific notation (the studio's large-design dialog said "7e+08 elements ... 48970 s").
#include "core/number_text.h"

#include <gtest/gtest.h>

#include <limits>

namespace paver {
namespace {

TEST(NumberText, LargeFiguresAreRoundedAndGroupedInThousands) {
  EXPECT_EQ(rounded_figure_text(2'670'123), "2,670,000");
  EXPECT_EQ(rounded_figure_text(7.04e8), "704,000,000");
  EXPECT_EQ(rounded_figure_text(1399.1), "1,400");
  EXPECT_EQ(rounded_figure_text(500000), "500,000");
  EXPECT_EQ(rounded_figure_text(999.6), "1,000");
  EXPECT_EQ(rounded_figure_text(123), "123");
  EXPECT_EQ(rounded_figure_text(8.44), "8.4");
  EXPECT_EQ(rounded_figure_text(5.0), "5");
  EXPECT_EQ(rounded_figure_text(-12345), "-12,300");
  EXPECT_EQ(rounded_figure_text(std::numeric_limits<double>::quiet_NaN()), "NaN");
}

TEST(NumberText, DurationsInTheUnitPeopleUse) {
  EXPECT_EQ(duration_text(45), "45 s");
  EXPECT_EQ(duration_text(186.9), "3 minutes");
  EXPECT_EQ(duration_text(48970), "13.6 hours");
  EXPECT_EQ(duration_text(3 * 86400.0), "3 days");
}

}  // namespace
}  // namespace paver
