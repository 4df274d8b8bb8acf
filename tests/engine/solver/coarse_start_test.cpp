// Tests for engine/solver/coarse_start.cpp and the vacancies of collision resolution: a lattice of
// about 20k points on the saddle, where 200 iterations from the regular lattice leave it squeezed,
// relaxes when it starts from the same design relaxed at coarser spacings. Every figure is checked
// against an all-pairs count, not the solver's own grids.
#include "all_pairs.h"
#include "pattern/default_spacing.h"
#include "pipeline/pavement.h"
#include "surface_maps.h"

#include <gtest/gtest.h>

namespace paver {
namespace {

// At the paper's filter rate for stretched springs (0.5), where the paper's stage alone shows
// what the start does; the default (0.75) packs tighter and leaves more to collision resolution.
Design saddle_design(double spacing_share, int coarse_levels, double mu_stretched = 0.5) {
  const auto map = test::named_map("saddle");
  Design design;
  design.pattern.tessellation = Tessellation::Triangle;
  design.pattern.topology = Topology::Lattice;
  design.pattern.spacing = default_spacing(map->mesh, Tessellation::Triangle) * spacing_share;
  design.solver.coarse_levels = coarse_levels;
  design.solver.mu_stretched = mu_stretched;
  return design;
}

// The 20k-point saddle at the default filter rate, from its multilevel start (shared by two tests:
// it takes seconds).
const Pavement& default_rate_saddle() {
  static const Pavement pavement =
      make_pavement(*test::named_map("saddle"), saddle_design(1 / 4.5, 8, SolverParams{}.mu_stretched));
  return pavement;
}

TEST(CoarseStart, ALargeLatticeRelaxesFromItsCoarseShapeWhereTheRegularStartStaysSqueezed) {
  const auto map = test::named_map("saddle");
  const Pavement coarse = make_pavement(*map, saddle_design(1 / 4.5, 8));
  const Pavement regular = make_pavement(*map, saddle_design(1 / 4.5, 0));
  ASSERT_GT(coarse.pattern.point_count(), 15000);

  // Levels at 2x, 4x, ... the spacing, a quarter of the points each, none under the floor.
  const CoarseStartReport& levels = coarse.coarse_start;
  ASSERT_GE(levels.level_points.size(), 2u);
  for (size_t k = 0; k < levels.level_points.size(); ++k) {
    EXPECT_GE(levels.level_points[k], kCoarseStartMinPoints);
    const int finer = k == 0 ? coarse.pattern.point_count() : levels.level_points[k - 1];
    EXPECT_NEAR(double(levels.level_points[k]) / finer, 0.25, 0.05);
  }
  EXPECT_TRUE(regular.coarse_start.level_points.empty());

  // The paper's iteration from the regular lattice leaves rows squeezed; from the coarse shape it does not.
  EXPECT_GT(regular.paper.contact_violations, 10000);
  EXPECT_LT(coarse.paper.contact_violations, regular.paper.contact_violations / 10);
  EXPECT_LT(regular.paper.neighbor_ratio.p5, 0.9);
  EXPECT_GT(coarse.paper.neighbor_ratio.p5, 0.98);
  EXPECT_GE(coarse.after.fill, 0.88);
  EXPECT_GT(coarse.after.fill, regular.after.fill + 0.05);

  // At the default filter rate the paper's stage leaves more pairs in contact, and resolution
  // makes up for them: the final pavement is at least as full.
  const Pavement& tighter = default_rate_saddle();
  EXPECT_GT(tighter.paper.contact_violations, coarse.paper.contact_violations);
  EXPECT_GE(tighter.after.fill, coarse.after.fill);

  for (const Pavement* p : {&coarse, &regular, &tighter}) {
    const test::AllPairs truth = test::all_pairs(p->elements, 0);
    EXPECT_EQ(truth.violations, 0);
    EXPECT_EQ(p->after.contact_violations, truth.violations);
  }
}

TEST(CoarseStart, ASmallDesignIsThePapersMethodUnchanged) {
  const auto map = test::named_map("saddle");
  const Pavement p = make_pavement(*map, saddle_design(1, 8));
  EXPECT_LT(p.pattern.point_count(), 4 * kCoarseStartMinPoints);
  EXPECT_TRUE(p.coarse_start.level_points.empty());
  EXPECT_EQ(p.coarse_start.retired, 0);
}

TEST(CollisionResolution, WhereContactSpringsStallVacanciesResolveTheRest) {
  // From the regular start the saddle's large lattice is squeezed along lines: contact springs push
  // one pair apart into the next, so resolution turns to retiring particles.
  const auto map = test::named_map("saddle");
  const Pavement p = make_pavement(*map, saddle_design(1 / 4.5, 0, SolverParams{}.mu_stretched));
  EXPECT_GT(p.resolution.retired, 0);
  // Vacancies let the pattern relax: far fewer elements are left to remove than were retired.
  EXPECT_LT(p.resolution.removed, p.resolution.retired);
  EXPECT_EQ(test::all_pairs(p.elements, 0).violations, 0);
}

TEST(CollisionResolution, ALargePatternEndsItsRoundsWhenFewPairsAreLeft) {
  // The saddle's 20k-point lattice resolved as usual and as a large pattern (the threshold lowered
  // to it): after its first round it stops once it has fewer colliding pairs than 1% of its
  // elements, and leaves them to the last resort.
  const auto map = test::named_map("saddle");
  PavementOptions large;
  large.resolution.large_pattern_particles = 10000;
  const Pavement& usual = default_rate_saddle();
  const Pavement early = make_pavement(*map, saddle_design(1 / 4.5, 8, SolverParams{}.mu_stretched), large);
  ASSERT_GT(early.pattern.point_count(), large.resolution.large_pattern_particles);
  ASSERT_LT(usual.pattern.point_count(), CollisionResolutionOptions{}.large_pattern_particles);

  const double share = large.resolution.large_pattern_pairs_share;
  ASSERT_GT(early.paper.contact_violations, share * early.paper.elements);  // work for more than one round
  EXPECT_LT(early.resolution.rounds, usual.resolution.rounds);
  EXPECT_LT(early.resolution.pairs_left, share * early.paper.elements);
  EXPECT_GT(early.resolution.removed, usual.resolution.removed);
  EXPECT_GE(early.after.fill, 0.9);
  const test::AllPairs truth = test::all_pairs(early.elements, 0);
  EXPECT_EQ(truth.violations, 0);
  EXPECT_EQ(early.after.contact_violations, truth.violations);
}

}  // namespace
}  // namespace paver
