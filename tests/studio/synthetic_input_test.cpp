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

TEST(SyntheticInput, TypingClicksIntoTheFieldTypesACharacterAFrameAndLetsGo) {
  const auto entered = typing_frames({50, 60}, "0-5", TypeEnd::Enter, {900, 790});
  ASSERT_EQ(entered.size(), 3u + 3u + 2u) << "click, one frame a character, Enter down and up";
  EXPECT_TRUE(entered[1].left_down) << "the click that focuses (and selects) the field";
  EXPECT_EQ(entered[3].text, "0");
  EXPECT_EQ(entered[4].text, "-");
  EXPECT_EQ(entered[5].text, "5");
  EXPECT_EQ(entered[6].key, GLFW_KEY_ENTER);
  const auto tabbed = typing_frames({50, 60}, "1", TypeEnd::Tab, {900, 790});
  EXPECT_EQ(tabbed[4].key, GLFW_KEY_TAB);
  const auto away = typing_frames({50, 60}, "\xc2\xb5m", TypeEnd::Away, {900, 790});
  ASSERT_EQ(away.size(), 3u + 2u + 3u) << "a UTF-8 character is one frame";
  EXPECT_EQ(away[3].text, "\xc2\xb5");
  EXPECT_EQ(away.back().mouse, glm::vec2(900, 790)) << "let go by a click elsewhere";
  EXPECT_TRUE(away[6].left_down);
}

}  // namespace
}  // namespace paver::studio
