// placement.band_rows auto: a band is closed both ways and, paved both ways, the way with an ok
// verdict and the most elements is kept. Rows across filled the bundled bands better at the default spacing; a ring of large stones
// across its width kept one stone in two columns (7 stones of 5 mm round a ring, a jeweller's
// trial), where one row along it goes all round.
#include "design/design.h"
#include "input_error_assertions.h"
#include "io/design_io.h"
#include "pipeline/pavement.h"
#include "surface_maps.h"
#include "test_meshes.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace paver {
namespace {

Design ring_of_stones(double stone) {
  Design design;
  design.pattern.tessellation = Tessellation::Triangle;
  design.elements.gap = 0.1;
  set_stone_size(design, stone);
  return design;
}

Pavement paved_with_rows(const SurfaceMap& map, Design design, BandRows rows) {
  design.placement.band_rows = rows;
  return make_pavement(map, design);
}

// Stones keep their size, so a way round the band with room for fewer than three of them cannot
// close it (it shrank D under the stones and was refused for their overlap, which the design does
// not have): named, the run says why and how large D may be; auto leaves that way out.
TEST(BandRows, AWayRoundWithNoRoomForThreeStonesIsRefusedSayingWhy) {
  const SurfaceMap& map = *test::bundled_map("ring_band");
  const std::string across = test::error_of([&] { paved_with_rows(map, ring_of_stones(15), BandRows::Across); });
  EXPECT_TRUE(test::Contains(across, "rows across the band need 3 lattice steps around it")) << across;
  EXPECT_TRUE(test::Contains(across, "that way D is at most")) << across;
  const std::string automatic = test::error_of([&] { make_pavement(map, ring_of_stones(15)); });
  EXPECT_FALSE(test::Contains(automatic, "overlap")) << automatic;
  // Where both ways close, auto still compares them (the 5 mm ring below).
}

TEST(BandRows, AutoLaysARowOfLargeStonesAllRoundARing) {
  const SurfaceMap& map = *test::bundled_map("ring_band");
  const Design design = ring_of_stones(5);
  ASSERT_EQ(design.placement.band_rows, BandRows::Auto) << "the default";
  const Pavement automatic = make_pavement(map, design);
  ASSERT_TRUE(automatic.seamless && automatic.band_closure);
  const BandClosure& closure = *automatic.band_closure;
  EXPECT_FALSE(closure.rows_across);
  EXPECT_GT(closure.laid_out_along, closure.laid_out_across);
  EXPECT_GT(closure.kept_along, closure.kept_across) << "a band this small is paved both ways";
  EXPECT_EQ(automatic.design.placement.band_rows, BandRows::Along) << "the design as used names the way taken";
  EXPECT_EQ(automatic.after.contact_violations, 0);
  const Pavement across = paved_with_rows(map, design, BandRows::Across);
  const Pavement along = paved_with_rows(map, design, BandRows::Along);
  EXPECT_GE(automatic.elements.size(), 12u);
  EXPECT_GT(automatic.elements.size(), across.elements.size());
  EXPECT_EQ(automatic.elements.position, along.elements.position) << "auto lays what naming the way lays";
  EXPECT_EQ(along.band_closure->laid_out_along, 0u) << "named rows are not compared";
  // Its written design lays the same stones again.
  const Pavement again = make_pavement(map, design_from_json(design_to_json(automatic.design), "design.json"));
  EXPECT_EQ(again.elements.position, automatic.elements.position);
}

TEST(BandRows, AutoKeepsRowsAcrossWhereTheyKeepMoreOnTheBundledBangle) {
  const SurfaceMap& map = *test::bundled_map("bangle");
  const Design design = load_design(test::source_dir() / "assets/designs/bangle_tri_gems.json");
  const Pavement automatic = make_pavement(map, design);
  ASSERT_TRUE(automatic.band_closure);
  EXPECT_TRUE(automatic.band_closure->rows_across);
  // Along lays out more (642 against 620) but keeps fewer once optimized: the pavements decide.
  EXPECT_GT(automatic.band_closure->laid_out_along, automatic.band_closure->laid_out_across);
  EXPECT_GT(automatic.band_closure->kept_across, 0u);
  EXPECT_GE(automatic.band_closure->kept_across, automatic.band_closure->kept_along);
  EXPECT_EQ(automatic.elements.position, paved_with_rows(map, design, BandRows::Across).elements.position);
}

// Element edits name the elements of one lattice: under them auto does not choose, it takes across.
TEST(BandRows, UnderEditsAutoTakesRowsAcross) {
  const SurfaceMap& map = *test::bundled_map("ring_band");
  Design design = ring_of_stones(5);
  design.pattern.topology = Topology::Lattice;  // edits name a lattice's elements (auto is refused)
  const Pavement laid = paved_with_rows(map, design, BandRows::Across);
  design.edits.deleted.push_back({laid.elements.id.front(), laid.elements.uv.front()});
  const Pavement edited = make_pavement(map, design);
  ASSERT_TRUE(edited.band_closure);
  EXPECT_TRUE(edited.band_closure->rows_across);
  EXPECT_EQ(edited.band_closure->laid_out_along + edited.band_closure->laid_out_across, 0u) << "no choice made";
  EXPECT_EQ(edited.deletions_missed, 0);
  EXPECT_EQ(edited.elements.size() + 1, laid.elements.size());
}

}  // namespace
}  // namespace paver
