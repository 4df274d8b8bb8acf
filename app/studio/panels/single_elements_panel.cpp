// Under the elements panel: the single elements the designer edited. The selected element (what
// it is, pin / unpin, delete, move by a number of spacings), how to edit in the views, and the
// design's edits with a way to drop them all.
#include "panels.h"

#include "../element_editing.h"
#include "../studio.h"

#include "core/input_error.h"

#include <algorithm>
#include <cstdio>
#include <string>

namespace paver::studio {

void single_elements_panel(Studio& s) {
  section("Single stones");
  ImGui::Checkbox("edit stones in the views (E)", &s.ui.edit_elements);
  help_marker("Click a stone to select it, in either view. Drag it to move it (in the 3D view it slides along the "
              "surface): it stays where you drop "
              "it and its neighbours within three spacings make room; Ctrl+click adds a stone of the vertex size. "
              "Del deletes the selected stone (its place stays empty), P pins it and Shift+P lets it go (a pinned stone stays "
              "put while the rest relaxes; an orange dot marks it, and the stones you added). Edits are undoable, saved in the design file, and `paver run` repeats "
              "them. Shift+drag in the 2D map selects every stone in a box: Del, P and Shift+P then take them all.");
  const Pavement* pavement = s.doc.result.pavement.get();
  if (!s.ui.box_selected.empty()) {
    ImGui::Text("%zu stones selected (a box)", selection(s.ui).size());
    if (ImGui::Button("pin all (P)")) pin_selected(s, true);
    ImGui::SameLine();
    if (ImGui::Button("unpin all")) pin_selected(s, false);
    ImGui::SameLine();
    if (ImGui::Button("delete all (Del)")) delete_selected(s);
    ImGui::SameLine();
    if (ImGui::Button("deselect (Esc)")) clear_selection(s.ui);
  } else if (s.ui.selected_element >= 0 && pavement && find_element(*pavement, s.ui.selected_element)) {
    const int id = s.ui.selected_element;
    // One fact a line: wrapping broke a number after its point ("u 5." / "695").
    const std::string text = describe_element(s.doc.design, *pavement, id);
    for (std::size_t from = 0; from < text.size();) {
      const std::size_t to = std::min(text.find(", ", from), text.size());
      ImGui::TextUnformatted(text.c_str() + from, text.c_str() + to);
      from = to + 2;
    }
    const bool pinned = is_pinned(s.doc.design, *pavement, id);
    if (ImGui::Button(pinned ? "unpin (Shift+P)" : "pin (P)")) pin_selected(s, !pinned);
    ImGui::SameLine();
    if (ImGui::Button("delete (Del)")) delete_selected(s);
    // Typed numbers apply on the button, not on every keystroke.
    ImGui::SetNextItemWidth(160);
    ImGui::InputScalarN("move by (x D)", ImGuiDataType_Double, &s.ui.move_by.x, 2, nullptr, nullptr, "%.3f");
    help_marker("How far to move the selected stone in the 2D map, in spacings D: across and up.");
    if (ImGui::Button("move")) move_selected(s, s.ui.move_by * pavement->design.pattern.spacing);
  } else {
    ImGui::TextDisabled("no stone selected");
  }
  const ElementEdits& edits = s.doc.design.edits;
  ImGui::Text("edits: %zu moved (%d pinned), %zu added, %zu deleted", edits.moved.size(), edits.pinned_count(), edits.added.size(),
              edits.deleted.size());
  if (pavement && pavement->deletions_missed > 0)
    ImGui::TextWrapped("%d deletions found no element: refilled stones that an edit moved away", pavement->deletions_missed);
  if (!edits.empty() && ImGui::Button("clear all edits")) {
    Design d = s.doc.design;
    d.edits = {};
    change_design(s.doc, d);
    clear_selection(s.ui);
  }
}

}  // namespace paver::studio
