// The one chooser (pipeline/choices.h) on fixture pavements: the better by the one ranking kept
// (fewer verdict problems, then the higher fill), the first among equals, candidates skipped when
// not worth trying or after a stop, and the dropped ones' time.
#include "pipeline/choices.h"

#include "report/verdict.h"

#include <gtest/gtest.h>

#include <atomic>

namespace paver {
namespace {

// A pavement with `elements` elements, fill `fill`, `violations` contact violations (one verdict
// problem when > 0) and its stages taking `ms`.
Pavement fixture(int elements, double fill, long violations = 0, double ms = 10) {
  Pavement p;
  for (int i = 0; i < elements; ++i)
    p.elements.push_back(ElementKind::Vertex, i, 0, {}, {}, {0, 0, 1}, 1, ShapeKind::Gem);
  p.after.fill = fill;
  p.after.contact_violations = violations;
  p.timings = {{"pattern", ms}};
  return p;
}

Candidate paving(std::string name, Pavement p, int* paved = nullptr) {
  return {std::move(name),
          [p, paved](const Pavement*) {
            if (paved) ++*paved;
            return p;
          },
          {}};
}

TEST(BestOf, KeepsFewerProblemsBeforeAHigherFillAndTheFirstAmongEquals) {
  ASSERT_FALSE(judge_pavement(fixture(1, 0.9, 3).after).ok) << "the fixture's violations are a verdict problem";
  Choice fewer = best_of({paving("a", fixture(100, 0.99, 2)), paving("b", fixture(90, 0.90))}, nullptr);
  EXPECT_EQ(fewer.kept_index, 1) << "an ok verdict before a fuller NOT OK one";
  Choice fuller = best_of({paving("a", fixture(100, 0.90)), paving("b", fixture(110, 0.95))}, nullptr);
  EXPECT_EQ(fuller.kept_index, 1);
  EXPECT_EQ(fuller.kept.elements.size(), 110u) << "the kept pavement is the candidate's own, not paved again";
  Choice tie = best_of({paving("a", fixture(100, 0.95)), paving("b", fixture(100, 0.95))}, nullptr);
  EXPECT_EQ(tie.kept_index, 0) << "a choice that gains nothing changes nothing";
  EXPECT_EQ(tie.elements, (std::vector<long>{100, 100}));
  ASSERT_EQ(tie.dropped.size(), 1u);
  EXPECT_EQ(tie.dropped[0].first, "b_tried");
  EXPECT_EQ(tie.dropped[0].second, 10);
}

TEST(BestOf, ACandidateNotWorthTryingIsNotPavedAndSeesTheBestSoFar) {
  int paved = 0;
  Candidate second = paving("second", fixture(200, 0.99), &paved);
  double seen_fill = 0;
  second.worth_trying = [&](const Pavement& best) {
    seen_fill = best.after.fill;
    return best.after.fill < 0.85;
  };
  const Choice choice = best_of({paving("first", fixture(100, 0.9)), second}, nullptr);
  EXPECT_EQ(paved, 0);
  EXPECT_EQ(seen_fill, 0.9);
  EXPECT_EQ(choice.kept_index, 0);
  EXPECT_EQ(choice.elements[1], -1);
  EXPECT_FALSE(choice.quality[1].has_value());
  EXPECT_TRUE(choice.dropped.empty());
}

TEST(BestOf, AStopPavesTheFirstOnly) {
  std::atomic<bool> stop{true};
  int paved = 0;
  const Choice choice =
      best_of({paving("first", fixture(100, 0.9), &paved), paving("second", fixture(200, 0.99), &paved)}, &stop);
  EXPECT_EQ(paved, 1);
  EXPECT_EQ(choice.kept_index, 0);
}

}  // namespace
}  // namespace paver
