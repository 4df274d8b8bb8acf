#include "report/ring_size.h"

#include "core/input_error.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <numbers>

namespace paver {
namespace {

// The three systems' formulas, against sizes a ring gauge shows (docs/stones.md, "Ring sizes").
TEST(RingSize, SizesGiveTheInsideDiametersOfTheirTables) {
  EXPECT_NEAR(ring_inside_diameter_mm(RingSizeSystem::US, "7"), 17.32, 0.005);
  EXPECT_NEAR(ring_inside_diameter_mm(RingSizeSystem::US, "0"), 11.63, 1e-12);
  EXPECT_NEAR(ring_inside_diameter_mm(RingSizeSystem::US, "6.5") + 0.8128 / 2, 17.32, 0.005);
  EXPECT_NEAR(ring_inside_diameter_mm(RingSizeSystem::EU, "54"), 54 / std::numbers::pi, 1e-12);
  EXPECT_NEAR(ring_inside_diameter_mm(RingSizeSystem::UK, "A"), 37.5 / std::numbers::pi, 1e-12);
  EXPECT_NEAR(ring_inside_diameter_mm(RingSizeSystem::UK, "N1/2"), 17.31, 0.005);  // UK N 1/2 is US 7
  EXPECT_EQ(ring_inside_diameter_mm(RingSizeSystem::UK, "n.5"), ring_inside_diameter_mm(RingSizeSystem::UK, "N1/2"));
  EXPECT_GT(ring_inside_diameter_mm(RingSizeSystem::UK, "O"), ring_inside_diameter_mm(RingSizeSystem::UK, "N1/2"));
}

TEST(RingSize, SizesOffTheTableAreRefusedWithTheirRange) {
  for (const auto& [system, size, says] :
       {std::tuple{RingSizeSystem::US, "17", "from 0 to 16"}, std::tuple{RingSizeSystem::US, "seven", "from 0 to 16"},
        std::tuple{RingSizeSystem::US, "nan", "from 0 to 16"}, std::tuple{RingSizeSystem::EU, "17", "from 38 to 76"},
        std::tuple{RingSizeSystem::UK, "7", "a letter A to Z"}, std::tuple{RingSizeSystem::UK, "N3/4", "a letter A to Z"}}) {
    try {
      ring_inside_diameter_mm(system, size);
      ADD_FAILURE() << size << " was taken";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    }
  }
}

TEST(RingSize, TheNearestSizesReadBackToTheirOwnDiameters) {
  const nlohmann::json sizes = nearest_ring_sizes_json(17.3);
  EXPECT_EQ(sizes["US"]["size"], "7");
  EXPECT_EQ(sizes["UK"]["size"], "N1/2");
  EXPECT_EQ(sizes["EU"]["size"], "54.3");
  for (const auto& [name, system] : {std::pair{"US", RingSizeSystem::US}, std::pair{"EU", RingSizeSystem::EU},
                                     std::pair{"UK", RingSizeSystem::UK}}) {
    const double d = ring_inside_diameter_mm(system, sizes[name]["size"].get<std::string>());
    EXPECT_NEAR(sizes[name]["inside_diameter_mm"].get<double>(), d, 0.005) << name;
    EXPECT_NEAR(d, 17.3, 0.32) << name << ": the nearest size is within half a step";
  }
  EXPECT_EQ(nearest_ring_sizes_json(1.0)["US"]["size"], "0") << "below the table: its first size";
}

}  // namespace
}  // namespace paver
