#pragma once
// The studio's panels: free functions that draw the parts they are given, every frame, and
// change the design only through change_design (so each change is undoable and re-runs).
#include "../number_rules.h"
#include "core/enum_names.h"

#include <glm/vec2.hpp>

#include <imgui.h>

#include <algorithm>
#include <initializer_list>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

namespace paver::studio {

struct Document;
struct Studio;
struct UiState;

void side_panels(Studio& s, ImVec2 pos, ImVec2 size);  // the tabbed column of the panels below
void pattern_panel(Document& doc, UiState& ui);        // tessellation, D, operators, unit-cell editor
void elements_panel(Document& doc, UiState& ui);       // V- and E-elements, custom shape
void single_elements_panel(Studio& s);                 // the selected stone, pin / delete / move, the edits
void optimization_panel(Studio& s);                    // solver parameters, backend, run control
void report_panel(const Studio& s);                    // quality figures, iterations, timings, histogram
void file_panel(Studio& s);                            // open, recent, design, export, undo/redo
void help_panel();                                     // shortcuts

void views_area(Studio& s, ImVec2 pos, ImVec2 size);   // the 3D and 2D views with their controls
void status_bar(Studio& s, ImVec2 pos, ImVec2 size);
void panel_splitter(Studio& s, ImVec2 pos, float height);  // drag it to resize the side panels
void dialogs(Studio& s);                               // the error dialog, quit with unsaved changes
void file_dialog(Studio& s);                           // the file browser, and Save as's replace question

// A "(?)" after the last item, with `text` as its tooltip.
void help_marker(const char* text);
// A number field that applies when it lets go (Enter, Tab, a click elsewhere), never on every
// keystroke (typing 0.5 must not pave at 0 first); true when the value changed. Text that is no
// number or out of `rule`'s range is refused at the field: outlined, its reason under it, kept as
// typed, and posted to the status line (number_rules.h).
bool typed_number(const char* label, double& value, const char* format = "%.4g", const NumberRule& rule = {});
// Where the field of this label (before any "##") was drawn, if it was this frame or the last:
// a script's `type` clicks there, as a designer does.
void remember_field_place(const char* label);
std::optional<glm::vec2> field_centre(std::string_view label);
// Whether the field had the keyboard in frame `frame` or after: a script's typing reached it.
bool field_was_active_since(std::string_view label, int frame);
// A separator with a title under it.
void section(const char* title);

// A list to choose one of an enum's values from, each in `words` (in the enum's own order, as
// EnumNames lists them); true when the choice changed.
template <NamedEnum E, std::size_t N>
bool enum_combo(const char* label, E& value, const char* const (&words)[N]) {
  const std::vector<E> values = enum_values<E>();
  int current = int(std::find(values.begin(), values.end(), value) - values.begin());
  if (!ImGui::Combo(label, &current, words, int(std::min(N, values.size())))) return false;
  const bool changed = values[std::size_t(current)] != value;
  value = values[std::size_t(current)];
  return changed;
}

// Radio buttons on one line, one per (label, value); true when the choice changed.
template <class E>
bool radio_buttons(E& value, std::initializer_list<std::pair<const char*, E>> choices) {
  int current = int(value);
  bool first = true;
  for (const auto& [label, choice] : choices) {
    if (!first) ImGui::SameLine();
    first = false;
    ImGui::RadioButton(label, &current, int(choice));
  }
  const bool changed = E(current) != value;
  value = E(current);
  return changed;
}

}  // namespace paver::studio
