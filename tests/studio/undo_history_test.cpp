#include "undo_history.h"

#include <gtest/gtest.h>

namespace paver::studio {
namespace {

Design with_dt(double dt) {
  Design d;
  d.solver.dt = dt;
  return d;
}

TEST(UndoHistory, StartsEmpty) {
  UndoHistory h;
  EXPECT_FALSE(h.can_undo());
  EXPECT_FALSE(h.can_redo());
  EXPECT_FALSE(h.undo(with_dt(0.3)).has_value());
  EXPECT_FALSE(h.redo(with_dt(0.3)).has_value());
}

TEST(UndoHistory, UndoesAndRedoesInOrder) {
  UndoHistory h;
  Design current = with_dt(0.1);
  for (double dt : {0.2, 0.3, 0.4}) {
    h.record(current);
    current = with_dt(dt);
  }
  EXPECT_EQ(h.undo_count(), 3u);
  for (double expected : {0.3, 0.2, 0.1}) {
    auto previous = h.undo(current);
    ASSERT_TRUE(previous);
    EXPECT_EQ(previous->solver.dt, expected);
    current = *previous;
  }
  EXPECT_FALSE(h.can_undo());
  EXPECT_EQ(h.redo_count(), 3u);
  for (double expected : {0.2, 0.3, 0.4}) {
    auto next = h.redo(current);
    ASSERT_TRUE(next);
    EXPECT_EQ(next->solver.dt, expected);
    current = *next;
  }
  EXPECT_FALSE(h.can_redo());
}

TEST(UndoHistory, ANewChangeForgetsWhatCouldBeRedone) {
  UndoHistory h;
  h.record(with_dt(0.1));
  auto previous = h.undo(with_dt(0.2));
  ASSERT_TRUE(previous);
  EXPECT_TRUE(h.can_redo());
  h.record(*previous);  // a different change from 0.1
  EXPECT_FALSE(h.can_redo());
  EXPECT_EQ(h.undo_count(), 1u);
}

TEST(UndoHistory, KeepsTheNewestStepsUpToItsLimit) {
  UndoHistory h(3);
  for (int i = 0; i < 5; ++i) h.record(with_dt(0.1 * i));
  EXPECT_EQ(h.undo_count(), 3u);
  Design current = with_dt(9);
  for (double expected : {0.4, 0.3, 0.2}) {
    auto previous = h.undo(current);
    ASSERT_TRUE(previous);
    EXPECT_DOUBLE_EQ(previous->solver.dt, expected);
    current = *previous;
  }
  EXPECT_FALSE(h.can_undo());
}

TEST(UndoHistory, KeepsWholeDesigns) {
  UndoHistory h;
  Design before;
  before.pattern.tessellation = Tessellation::Grid;
  before.elements.edge.push_back({.t = 0.25, .scale = 0.4, .shape = ShapeKind::Gem, .cell_edges = {1}});
  before.placement.rotation_deg = 30;
  h.record(before);
  auto back = h.undo(Design{});
  ASSERT_TRUE(back);
  EXPECT_EQ(back->pattern.tessellation, Tessellation::Grid);
  ASSERT_EQ(back->elements.edge.size(), 1u);
  EXPECT_EQ(back->elements.edge[0].cell_edges, std::vector<int>{1});
  EXPECT_EQ(back->placement.rotation_deg, 30);
  h.clear();
  EXPECT_FALSE(h.can_undo());
  EXPECT_FALSE(h.can_redo());
}

}  // namespace
}  // namespace paver::studio
