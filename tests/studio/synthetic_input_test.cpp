#include "synthetic_input.h"

#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

namespace paver::studio {
namespace {

TEST(SyntheticInput, AClickMovesPressesAndReleasesWithItsModifier) {
  const auto frames = click_frames({10, 20}, false, true);
  ASSERT_EQ(frames.size(), 3u);
  EXPECT_FALSE(frames[0].left_down) << "the pointer arrives first, so the press lands on what is under it";
  EXPECT_TRUE(frames[1].left_down);
  EXPECT_FALSE(frames[2].left_down);
  for (const InputFrame& f : frames) {
    EXPECT_EQ(f.mouse, glm::vec2(10, 20));
    EXPECT_TRUE(f.ctrl);
    EXPECT_FALSE(f.shift);
  }
}

TEST(SyntheticInput, ADragHoldsTheButtonFromStartToEnd) {
  const auto frames = drag_frames({0, 0}, {80, 40}, true, false, 4);
  ASSERT_EQ(frames.size(), 7u);
  EXPECT_FALSE(frames.front().left_down);
  EXPECT_EQ(frames[1].mouse, glm::vec2(0, 0));
  for (std::size_t i = 1; i + 1 < frames.size(); ++i) EXPECT_TRUE(frames[i].left_down) << i;
  EXPECT_EQ(frames[3].mouse, glm::vec2(40, 20)) << "halfway at half the steps";
  EXPECT_EQ(frames.back().mouse, glm::vec2(80, 40));
  EXPECT_FALSE(frames.back().left_down) << "released at the end";
  EXPECT_TRUE(frames.back().shift);
}

TEST(SyntheticInput, KeysByName) {
  EXPECT_EQ(key_from_name("Delete"), GLFW_KEY_DELETE);
  EXPECT_EQ(key_from_name("E"), GLFW_KEY_E);
  EXPECT_FALSE(key_from_name("delete")) << "names as the help panel writes them";
  const auto frames = key_frames(GLFW_KEY_P, {5, 5});
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0].key, GLFW_KEY_P);
  EXPECT_EQ(frames[1].key, -1) << "released the next frame";
}

}  // namespace
}  // namespace paver::studio
