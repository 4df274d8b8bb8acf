#pragma once
// Mouse and key input that a script plays into the UI, one state per frame, through the same ImGui
// input the GLFW backend fills: the views' own mouse handling (select, drag, Ctrl+click, Shift+box)
// and the shortcuts run on it, so that tests under Xvfb drive what a designer's hand does.
#include <glm/vec2.hpp>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace paver::studio {

struct InputFrame {
  glm::vec2 mouse{0};      // window pixels
  bool left_down = false;
  bool shift = false, ctrl = false;
  int key = -1;            // a GLFW key held down this frame, or none
  std::string text{};      // characters typed this frame (UTF-8)
};

// How a typed value is let go, as a designer does: Enter, Tab to the next field, or a click elsewhere.
enum class TypeEnd { Enter, Tab, Away };

// Move to `at`, press, release: a click (held modifiers throughout).
std::vector<InputFrame> click_frames(glm::vec2 at, bool shift, bool ctrl);
// Press at `from`, move to `to` in `steps` frames, release there.
std::vector<InputFrame> drag_frames(glm::vec2 from, glm::vec2 to, bool shift, bool ctrl, int steps = 8);
// One key pressed for a frame and released, the mouse at `at` (where it was), Shift held or not.
std::vector<InputFrame> key_frames(int key, glm::vec2 at, bool shift = false);

// A click into the field at `field` (which selects its text), `text` typed a character a frame,
// then the field let go by `end` (Away: a click at `away`).
std::vector<InputFrame> typing_frames(glm::vec2 field, std::string_view text, TypeEnd end, glm::vec2 away);

// The GLFW key a script names (E, P, B, I, M, V, L, C, R, N, Delete, Escape, Space), or none.
std::optional<int> key_from_name(std::string_view name);

}  // namespace paver::studio
