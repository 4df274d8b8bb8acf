// Tests for engine/pipeline/pave_once.cpp: the pass's step table, each step on the state the
// steps before it leave (pave_until, then pave_step), checked with all-pairs counts written in the
// tests (tests/support/all_pairs.h), not the engine's grids: the rim rows step on the pierced
// pendant, the multilevel start inside the optimize step on a 4,000-point lattice, a stop, and a
// concrete design paved alike by the pass and by make_pavement.
#include "pipeline/pave_once.h"

#include "all_pairs.h"
#include "pattern/default_spacing.h"
#include "report/verdict.h"
#include "surface_maps.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <string>
#include <vector>

namespace paver {
namespace {

std::vector<std::string> step_names() {
  std::vector<std::string> names;
  for (const PaveStep& step : pave_steps()) names.emplace_back(step.name);
  return names;
}

TEST(PaveOnce, TheStepsRunInThePapersOrderEachTimedOnce) {
  EXPECT_EQ(step_names(), (std::vector<std::string>{"pattern", "measure_initial", "optimize", "measure_paper",
                                                    "resolve_collisions", "edits", "rim_rows", "refill",
                                                    "close_spots", "grade", "fill_sizes", "ids", "deletions", "measure",
                                                    "beads"}));
  Design design;
  design.pattern.tessellation = Tessellation::Triangle;
  design.pattern.spacing = 18;
  design.pattern.topology = Topology::Lattice;
  const Pavement p = pave_once(*test::bundled_map("saddle"), design);
  std::vector<std::string> timed;
  for (const auto& [stage, ms] : p.timings) timed.push_back(stage);
  // No edits, deletions or beads asked: those steps do not apply. Touching spheres on a tri
  // lattice are pave: rows along the rims and the spots closed, by default.
  EXPECT_EQ(timed, (std::vector<std::string>{"pattern", "measure_initial", "optimize", "measure_paper",
                                             "resolve_collisions", "rim_rows", "refill", "close_spots", "ids",
                                             "measure"}));
  EXPECT_EQ(p.design.elements.rim_rows, RimRows::All) << "auto, resolved for this pattern";
  design.elements.vertex.scale = 0.8;  // spaced wider: not pave, neither step
  timed.clear();
  for (const auto& [stage, ms] : pave_once(*test::bundled_map("saddle"), design).timings) timed.push_back(stage);
  EXPECT_EQ(timed, (std::vector<std::string>{"pattern", "measure_initial", "optimize", "measure_paper",
                                             "resolve_collisions", "refill", "ids", "measure"}));
  EXPECT_EQ(p.design.pattern.spacing, 18);
}

TEST(PaveOnce, AConcreteDesignPavesAsMakePavementPavesIt) {
  Design design;
  design.pattern.tessellation = Tessellation::Hexagon;
  design.pattern.spacing = 6;
  design.pattern.topology = Topology::Lattice;
  const SurfaceMap& map = *test::bundled_map("dome");
  const Pavement once = pave_once(map, design), made = make_pavement(map, design);
  ASSERT_EQ(once.elements.size(), made.elements.size());
  EXPECT_EQ(once.elements.position, made.elements.position) << "no choice to make: the same pass";
}

TEST(PaveOnce, TheRimRowsStepLaysARowAroundEveryHoleOnTheStateBeforeIt) {
  const SurfaceMap& map = *test::bundled_map("pendant_pierced");
  Design design;
  design.pattern.tessellation = Tessellation::Triangle;
  design.pattern.topology = Topology::Lattice;
  design.pattern.spacing = 1.6;
  design.elements.vertex.shape = ShapeKind::Gem;
  design.elements.vertex.scale = 1.5 / 1.6;
  design.elements.gap = 0.1;
  design.elements.rim_rows = RimRows::Holes;
  PaveState state = pave_until(map, design, {}, "rim_rows");
  const std::size_t before = state.pavement.elements.size();
  ASSERT_EQ(test::all_pairs(state.pavement.elements, design.elements.gap).violations, 0)
      << "the resolution before the step left no pair";
  pave_step("rim_rows", map, {}, state);
  const RimRowReport& rows = state.pavement.rim_rows;
  EXPECT_EQ(rows.loops, 3) << "the bail hole and the two piercings";
  EXPECT_GT(rows.placed, 3 * 6);
  EXPECT_EQ(state.pavement.elements.size(), before + std::size_t(rows.placed) - std::size_t(rows.made_way));
  EXPECT_EQ(test::all_pairs(state.pavement.elements, design.elements.gap).violations, 0)
      << "the rows and the pattern that made way keep the contact rule";
}

TEST(PaveOnce, TheOptimizeStepStartsALargeLatticeFromItsCoarseShape) {
  const SurfaceMap& map = *test::bundled_map("saddle");
  Design design;
  design.pattern.tessellation = Tessellation::Triangle;
  design.pattern.topology = Topology::Lattice;
  design.pattern.spacing = default_spacing(map.mesh, Tessellation::Triangle) / 2.5;  // ~6,000 points
  PaveState coarse = pave_until(map, design, {}, "optimize");
  ASSERT_GE(coarse.pavement.pattern.point_count(), 4000);
  PaveState regular = coarse;
  regular.design.solver.coarse_levels = 0;
  pave_step("optimize", map, {}, coarse);
  pave_step("optimize", map, {}, regular);
  ASSERT_FALSE(coarse.pavement.coarse_start.level_points.empty());
  EXPECT_TRUE(regular.pavement.coarse_start.level_points.empty()) << "coarse_levels 0 is the paper's start";
  EXPECT_GT(coarse.pavement.coarse_start.level_points.front(), 1000) << "each level of 1,000 points or more";
  EXPECT_LT(coarse.pavement.coarse_start.level_points.front(), coarse.pavement.pattern.point_count());
  EXPECT_NE(coarse.pavement.points, regular.pavement.points) << "the coarse shape moved the start";
}

TEST(PaveOnce, AStopEndsThePassBeforeTheNextStep) {
  std::atomic<bool> stop = false;
  PavementOptions options;
  options.stop = &stop;
  std::vector<std::string> started;
  options.on_stage = [&](const std::string& stage) {
    started.push_back(stage);
    if (stage == "measure_initial") stop = true;
  };
  Design design;
  design.pattern.spacing = 18;
  design.pattern.topology = Topology::Lattice;
  const Pavement p = pave_once(*test::bundled_map("saddle"), design, options);
  EXPECT_EQ(started, (std::vector<std::string>{"pattern", "measure_initial"}));
  EXPECT_EQ(p.solve.iterations, 0);
}

}  // namespace
}  // namespace paver
