#include "synthetic_input.h"

#include <GLFW/glfw3.h>

#include <array>
#include <utility>

namespace paver::studio {

std::vector<InputFrame> click_frames(glm::vec2 at, bool shift, bool ctrl) {
  return {{at, false, shift, ctrl}, {at, true, shift, ctrl}, {at, false, shift, ctrl}};
}

std::vector<InputFrame> drag_frames(glm::vec2 from, glm::vec2 to, bool shift, bool ctrl, int steps) {
  std::vector<InputFrame> frames = {{from, false, shift, ctrl}, {from, true, shift, ctrl}};
  for (int i = 1; i <= steps; ++i) frames.push_back({from + (to - from) * (float(i) / float(steps)), true, shift, ctrl});
  frames.push_back({to, false, shift, ctrl});
  return frames;
}

std::vector<InputFrame> key_frames(int key, glm::vec2 at, bool shift) {
  InputFrame down{at};
  down.key = key;
  down.shift = shift;
  InputFrame up{at};
  up.shift = shift;
  return {down, up};
}

std::vector<InputFrame> typing_frames(glm::vec2 field, std::string_view text, TypeEnd end, glm::vec2 away) {
  std::vector<InputFrame> frames = click_frames(field, false, false);
  for (std::size_t i = 0; i < text.size();) {
    // One character a frame, whole: a UTF-8 sequence is its lead byte and the continuation bytes.
    std::size_t length = 1;
    while (i + length < text.size() && (static_cast<unsigned char>(text[i + length]) & 0xC0) == 0x80) ++length;
    InputFrame typed{field};
    typed.text = std::string(text.substr(i, length));
    frames.push_back(std::move(typed));
    i += length;
  }
  switch (end) {
    case TypeEnd::Enter: for (InputFrame& f : key_frames(GLFW_KEY_ENTER, field)) frames.push_back(std::move(f)); break;
    case TypeEnd::Tab: for (InputFrame& f : key_frames(GLFW_KEY_TAB, field)) frames.push_back(std::move(f)); break;
    case TypeEnd::Away: for (InputFrame& f : click_frames(away, false, false)) frames.push_back(std::move(f)); break;
  }
  return frames;
}

std::optional<int> key_from_name(std::string_view name) {
  constexpr std::array<std::pair<std::string_view, int>, 13> kKeys = {{{"E", GLFW_KEY_E},
                                                                        {"B", GLFW_KEY_B},
                                                                        {"P", GLFW_KEY_P},
                                                                        {"I", GLFW_KEY_I},
                                                                        {"M", GLFW_KEY_M},
                                                                        {"V", GLFW_KEY_V},
                                                                        {"L", GLFW_KEY_L},
                                                                        {"C", GLFW_KEY_C},
                                                                        {"R", GLFW_KEY_R},
                                                                        {"N", GLFW_KEY_N},
                                                                        {"Delete", GLFW_KEY_DELETE},
                                                                        {"Escape", GLFW_KEY_ESCAPE},
                                                                        {"Space", GLFW_KEY_SPACE}}};
  for (const auto& [key_name, key] : kKeys)
    if (key_name == name) return key;
  return std::nullopt;
}

}  // namespace paver::studio
