// Tests for graded stones (issue 43; pattern/grade_field.cpp, elements/stone_grade.cpp): the
// pierced pendant and the ring band graded from their rims, the pendant by its curvature. Each
// pavement is checked apart from the engine: every pair in a loop, each stone's distance to the
// rims measured against the boundary here, the room left sampled over the whole surface
// (spot_probe.h), the sizes against the ladder a jeweller would buy.
#include "elements/stone_grade.h"

#include "all_pairs.h"
#include "core/input_error.h"
#include "pipeline/pavement.h"
#include "report/verdict.h"
#include "spot_probe.h"
#include "surface_maps.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>
#include <vector>

namespace paver {
namespace {

constexpr double kStone = 1.5, kGap = 0.1, kMargin = 0.3, kSmallest = 1.1;

Design graded_design(GradeBy by, double margin = kMargin) {
  Design design;
  design.pattern.tessellation = Tessellation::Triangle;
  design.elements.gap = kGap;
  design.elements.margin = margin;
  design.elements.grade = {by, kSmallest, 0, {}};
  set_stone_size(design, kStone);
  return design;
}

// The distance of p to the nearest boundary segment, by a loop over all of them.
double distance_to_rims(const SurfaceMesh& mesh, const glm::dvec3& p) {
  double best = std::numeric_limits<double>::infinity();
  for (const std::vector<int>& loop : mesh.boundary_loops)
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const glm::dvec3 a = mesh.positions[std::size_t(loop[k])], b = mesh.positions[std::size_t(loop[(k + 1) % loop.size()])];
      const double t = std::clamp(glm::dot(p - a, b - a) / std::max(glm::dot(b - a, b - a), 1e-300), 0.0, 1.0);
      best = std::min(best, glm::length(p - (a + t * (b - a))));
    }
  return best;
}

double mean(const std::vector<double>& v) { return v.empty() ? 0 : std::accumulate(v.begin(), v.end(), 0.0) / double(v.size()); }

// What every graded pavement must be: no pair under the gap, every stone a ladder's size between
// the smallest and the main, no place left where the smallest still fits, the verdict ok.
void expect_a_graded_pavement(const SurfaceMap& map, const Pavement& p, double margin) {
  const Elements& e = p.elements;
  EXPECT_EQ(test::all_pairs(e, kGap).violations, 0);
  EXPECT_EQ(p.after.contact_violations, 0);
  EXPECT_EQ(p.after.boundary_crossings, 0);
  ASSERT_FALSE(p.grade.ladder.empty());
  EXPECT_EQ(p.grade.ladder.front(), kStone);
  EXPECT_DOUBLE_EQ(p.grade.ladder.back(), kSmallest);
  std::set<double> used;
  for (const double d : e.diameter) used.insert(d);
  for (const double d : used)
    EXPECT_NE(std::find(p.grade.ladder.begin(), p.grade.ladder.end(), d), p.grade.ladder.end())
        << d << " mm is not a step of the ladder";
  EXPECT_GE(used.size(), 4u) << "a grade, not two sizes";
  for (std::size_t i = 0; i < e.size(); ++i)
    EXPECT_GE(distance_to_rims(map.mesh, e.position[i]), 0.5 * e.diameter[i] + margin - 1e-9) << "stone " << i;
  const test::SpotProbe bare =
      test::probe_spots(map.mesh, e, kGap, margin, kSmallest * (1 + 1e-6), kSmallest / 20, 4 * kStone);
  EXPECT_TRUE(bare.fitting.empty()) << bare.fitting.size() << " samples still fit the smallest graded stone";
  const Verdict verdict = judge_pavement(p.after);
  EXPECT_TRUE(verdict.ok) << (verdict.problems.empty() ? "" : verdict.problems.front());
}

TEST(StoneGrade, TheLadderStepsInStockedSizesOrInMeleeSieveSteps) {
  const SurfaceMap& map = *test::bundled_map("pendant_pierced");
  ElementsDesign elements;
  elements.grade = {GradeBy::Rim, 1.1, 0, {}};
  const GradeField sieve(map, elements, 1.5, 1.0);
  const std::vector<double> steps = sieve.ladder();
  ASSERT_EQ(steps.size(), 9u);  // 1.5, 1.45 ... 1.1
  for (std::size_t k = 0; k < steps.size(); ++k) EXPECT_NEAR(steps[k], 1.5 - 0.05 * double(k), 1e-12);
  // In inches the steps are still 0.05 mm.
  ElementsDesign in_inches;
  in_inches.grade = {GradeBy::Rim, 1.1 / 25.4, 0, {}};
  const GradeField inches(map, in_inches, 1.5 / 25.4, 25.4);
  EXPECT_EQ(inches.ladder().size(), 9u);

  elements.fill_sizes = {1.3, 0.9, 1.2, 1.6};  // only the stocked sizes between the smallest and the main
  const GradeField stocked(map, elements, 1.5, 1.0);
  EXPECT_EQ(stocked.ladder(), (std::vector<double>{1.5, 1.3, 1.2, 1.1}));
  EXPECT_EQ(stocked.stone_for(1.0), 1.5);
  EXPECT_EQ(stocked.stone_for(1.3 / 1.5), 1.3) << "a share exactly on a step gets that step";
  EXPECT_EQ(stocked.stone_for(0.85), 1.3) << "1.275 is nearer 1.3 than 1.2";
  EXPECT_EQ(stocked.stone_for(0.83), 1.2) << "1.245 is nearer 1.2";
  EXPECT_EQ(stocked.stone_for(0.9666), 1.5) << "1.45 is nearer 1.5 than 1.3";
  EXPECT_EQ(stocked.stone_for(1.25 / 1.5), 1.3) << "halfway: the larger";
  EXPECT_EQ(stocked.stone_for(0.1), 1.1) << "never under the smallest";
}

TEST(StoneGrade, ARimGradeIsSmallestAtTheMarginAndTheMainSizeAWidthIn) {
  const SurfaceMap& map = *test::bundled_map("pendant_pierced");
  ElementsDesign elements;
  elements.margin = kMargin;
  elements.grade = {GradeBy::Rim, kSmallest, 2.0, {}};
  const GradeField field(map, elements, kStone, 1.0);
  const SurfaceMesh& mesh = map.mesh;
  int near = 0, far = 0;
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const double d = distance_to_rims(mesh, mesh.positions[v]);
    const double share = field.share(mesh.positions[v], map.curvature[v]);
    EXPECT_GE(share, kSmallest / kStone - 1e-12);
    EXPECT_LE(share, 1.0);
    if (d <= kMargin + 0.5 * kSmallest) {
      EXPECT_NEAR(share, kSmallest / kStone, 1e-9) << "vertex " << v;
      ++near;
    }
    if (d >= kMargin + 0.5 * kSmallest + 2.0 + 1e-6) {
      EXPECT_EQ(share, 1.0) << "vertex " << v;
      ++far;
    }
  }
  EXPECT_GT(near, 0);
  EXPECT_GT(far, 0);
}

// By the curvature averaged over a stone, above the surface's base: a flat plate whose scan is a
// little rough keeps the main size everywhere (eq. 5's normalised curvature spread that noise over
// the whole grade), and the pendant's body keeps it while its tip takes the smallest.
TEST(StoneGrade, ACurvatureGradeIgnoresAFlatScansNoiseAndGradesATip) {
  const SurfaceMap plate = build_surface_map(test::grid_surface(60, 60, [](double u, double v) {
    return glm::dvec3(30 * u, 30 * v, 0.003 * std::sin(97 * u) * std::cos(89 * v));
  }));
  ElementsDesign elements;
  elements.grade = {GradeBy::Curvature, kSmallest, 0, {}};
  const GradeField flat(plate, elements, kStone, 1.0);
  for (std::size_t v = 0; v < plate.mesh.positions.size(); ++v)
    EXPECT_GT(flat.share(plate.mesh.positions[v], plate.curvature[v]), 0.98) << "vertex " << v;

  const SurfaceMap& pendant = *test::bundled_map("pendant");
  const GradeField field(pendant, elements, kStone, 1.0);
  double least = 1, most = 0;
  for (std::size_t v = 0; v < pendant.mesh.positions.size(); ++v) {
    const double share = field.share(pendant.mesh.positions[v], pendant.curvature[v]);
    least = std::min(least, share), most = std::max(most, share);
  }
  EXPECT_EQ(most, 1.0);
  EXPECT_NEAR(least, kSmallest / kStone, 1e-12) << "the tip takes the whole grade";
}

// Towards a point (the pendant's tip, its top at y 25.9): the smallest within the smallest stone's
// radius of it, the main size from `width` on, and never smaller farther out.
TEST(StoneGrade, APointGradeIsSmallestAtThePointAndTheMainSizeAWidthAway) {
  const SurfaceMap& map = *test::bundled_map("pendant");
  const glm::dvec3 tip(0, 25.9, 0);
  ElementsDesign elements;
  elements.grade = {GradeBy::Point, kSmallest, 8.0, {tip.x, tip.y, tip.z}};
  const GradeField field(map, elements, kStone, 1.0);
  std::vector<std::pair<double, double>> by_distance;  // (distance to the tip, share)
  for (std::size_t v = 0; v < map.mesh.positions.size(); ++v) {
    const double d = glm::length(map.mesh.positions[v] - tip);
    by_distance.emplace_back(d, field.share(map.mesh.positions[v], map.curvature[v]));
  }
  std::sort(by_distance.begin(), by_distance.end());
  ASSERT_LT(by_distance.front().first, 1.0) << "the pendant reaches its tip";
  EXPECT_NEAR(by_distance.front().second, kSmallest / kStone, 0.02);
  int far = 0;
  for (std::size_t k = 0; k < by_distance.size(); ++k) {
    const auto [d, share] = by_distance[k];
    EXPECT_GE(share, kSmallest / kStone - 1e-12);
    if (k > 0) {
      EXPECT_GE(share, by_distance[k - 1].second - 1e-12) << "the share falls again " << d << " from the tip";
    }
    if (d >= 8.0) {
      EXPECT_EQ(share, 1.0) << d << " from the tip";
      ++far;
    }
  }
  EXPECT_GT(far, int(by_distance.size()) / 2);
}

TEST(StoneGrade, APendantGradedTowardsItsTip) {
  const SurfaceMap& map = *test::bundled_map("pendant");
  Design design = graded_design(GradeBy::Point);
  design.elements.grade.point = {0, 25.9, 0};
  design.elements.grade.width = 10;
  const Pavement p = make_pavement(map, design);
  EXPECT_EQ(p.design.pattern.topology, Topology::Adaptive);
  expect_a_graded_pavement(map, p, kMargin);
  std::vector<double> at_tip, body;
  for (std::size_t i = 0; i < p.elements.size(); ++i) {
    const double d = glm::length(p.elements.position[i] - glm::dvec3(0, 25.9, 0));
    if (d < 3) at_tip.push_back(p.elements.diameter[i]);
    if (d > 12) body.push_back(p.elements.diameter[i]);
  }
  ASSERT_GE(at_tip.size(), 3u);
  ASSERT_GT(body.size(), 100u);
  EXPECT_LT(mean(at_tip), 1.2) << "the stones at the tip are the small ones";
  EXPECT_GT(mean(body), 1.45) << "the body keeps the main size";
  // Without the point the grade cannot apply: said, naming the key.
  Design no_point = graded_design(GradeBy::Point);
  const std::optional<std::string> problem = grade_problem(no_point);
  ASSERT_TRUE(problem);
  EXPECT_NE(problem->find("'elements.grade.point' as [x, y, z]"), std::string::npos) << *problem;
}

TEST(StoneGrade, APiercedPendantGradedFromItsRimsAndHoles) {
  const SurfaceMap& map = *test::bundled_map("pendant_pierced");
  const Pavement p = make_pavement(map, graded_design(GradeBy::Rim));
  EXPECT_EQ(p.design.pattern.topology, Topology::Adaptive);
  expect_a_graded_pavement(map, p, kMargin);
  // Small along every rim and hole, the main size inside: the stones within a stone of the
  // margin are smaller on average than those three stones in, and the smallest are on rims.
  std::vector<double> at_rims, inside;
  for (std::size_t i = 0; i < p.elements.size(); ++i) {
    const double in = distance_to_rims(map.mesh, p.elements.position[i]) - kMargin;
    if (in < kStone) at_rims.push_back(p.elements.diameter[i]);
    if (in > 3 * kStone) inside.push_back(p.elements.diameter[i]);
    if (p.elements.diameter[i] == kSmallest) {
      EXPECT_LT(in, 2 * kStone) << "a smallest stone far from every rim";
    }
  }
  ASSERT_GT(at_rims.size(), 50u);
  ASSERT_GT(inside.size(), 10u);
  EXPECT_LT(mean(at_rims), 1.2);
  EXPECT_GT(mean(inside), 1.4);
  // Smaller stones lie closer: more stones than the ungraded pavement of the same design.
  Design plain = graded_design(GradeBy::None);
  plain.pattern.topology = Topology::Adaptive;
  EXPECT_GT(p.elements.size(), make_pavement(map, plain).elements.size() * 5 / 4);
}

TEST(StoneGrade, ARingBandGradedTowardsBothEdges) {
  const SurfaceMap& map = *test::bundled_map("ring_band");
  Design design = graded_design(GradeBy::Rim, 0.2);
  design.elements.grade.width = 2;
  const Pavement p = make_pavement(map, design);
  expect_a_graded_pavement(map, p, 0.2);
  for (std::size_t i = 0; i < p.elements.size(); ++i) {
    const double in = distance_to_rims(map.mesh, p.elements.position[i]) - 0.2;
    if (in < 0.6 * kStone) {
      EXPECT_LE(p.elements.diameter[i], 1.2) << "an edge row stone of " << p.elements.diameter[i];
    }
  }
}

TEST(StoneGrade, ACurvatureGradeSetsTheSmallerStonesWhereTheSurfaceBends) {
  const SurfaceMap& map = *test::bundled_map("pendant");
  const Pavement p = make_pavement(map, graded_design(GradeBy::Curvature));
  expect_a_graded_pavement(map, p, kMargin);
  // The stones' sizes against the curvature at their centres (the map's, blended here): the
  // most curved quarter's stones are smaller on average than the flattest quarter's.
  std::vector<std::pair<double, double>> by_curvature;
  for (std::size_t i = 0; i < p.elements.size(); ++i) {
    double nearest = std::numeric_limits<double>::infinity(), kappa = 0;
    for (std::size_t v = 0; v < map.mesh.positions.size(); ++v)
      if (const double d = glm::length(map.mesh.positions[v] - p.elements.position[i]); d < nearest)
        nearest = d, kappa = map.curvature[v];
    by_curvature.emplace_back(kappa, p.elements.diameter[i]);
  }
  std::sort(by_curvature.begin(), by_curvature.end());
  const std::size_t quarter = by_curvature.size() / 4;
  std::vector<double> flat, curved;
  for (std::size_t k = 0; k < quarter; ++k) flat.push_back(by_curvature[k].second);
  for (std::size_t k = by_curvature.size() - quarter; k < by_curvature.size(); ++k) curved.push_back(by_curvature[k].second);
  EXPECT_LT(mean(curved) + 0.1, mean(flat));
}

TEST(StoneGrade, GradesThatCannotApplyAreRefusedNamingTheKey) {
  const SurfaceMap& pendant = *test::bundled_map("pendant_pierced");
  const auto refusal = [](const SurfaceMap& map, const Design& d) -> std::string {
    try {
      (void)make_pavement(map, d);
    } catch (const InputError& e) {
      return e.what();
    }
    return "paved";
  };
  Design lattice = graded_design(GradeBy::Rim);
  lattice.pattern.topology = Topology::Lattice;
  EXPECT_NE(refusal(pendant, lattice).find("'elements.grade.by' \"rim\": the lattice cannot grade its stones"), std::string::npos);
  Design hex = graded_design(GradeBy::Rim);
  hex.pattern.tessellation = Tessellation::Hexagon;
  EXPECT_NE(refusal(pendant, hex).find("only a tri pattern's stones are graded"), std::string::npos);
  Design larger = graded_design(GradeBy::Rim);
  larger.elements.grade.smallest = 1.6;
  EXPECT_NE(refusal(pendant, larger).find("is not smaller than the main stone (1.5)"), std::string::npos);
  Design tiny = graded_design(GradeBy::Rim);
  tiny.elements.grade.smallest = 0.3;
  EXPECT_NE(refusal(pendant, tiny).find("less than a quarter of the main stone"), std::string::npos);
  const SurfaceMap& bead = *test::bundled_map("bead");
  EXPECT_NE(refusal(bead, graded_design(GradeBy::Rim)).find("'elements.grade.by' \"rim\": the surface is closed, so it has no rim"), std::string::npos);
  Design none = graded_design(GradeBy::Curvature);
  none.elements.grade.smallest = 0;
  EXPECT_THROW(validate_design(none, "d.json"), InputError);
}

}  // namespace
}  // namespace paver
