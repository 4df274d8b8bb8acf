#pragma once
// The keyboard shortcuts: one table for the help panel and for handling them, so the two agree.
#include <string>
#include <vector>

namespace paver::studio {

struct Studio;

struct Shortcut {
  const char* keys;
  std::string action;
};
const std::vector<Shortcut>& shortcut_list();

// Acts on the shortcuts pressed this frame (none while a text box has the keyboard).
void handle_shortcuts(Studio& s);

}  // namespace paver::studio
