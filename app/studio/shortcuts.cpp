#include "shortcuts.h"

#include "design/design_keys.h"
#include "pipeline/pavement.h"
#include "studio.h"
#include "element_editing.h"

#include "core/input_error.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

namespace paver::studio {

const std::vector<Shortcut>& shortcut_list() {
  static const std::vector<Shortcut> list = {
      {"Ctrl+Z", "undo the last design change"},
      {"Ctrl+Y, Ctrl+Shift+Z", "redo"},
      {"Ctrl+S", "save the design (to the path in File)"},
      {"Ctrl+E", "export all outputs (to the folder in File)"},
      {"Ctrl+Q", "quit (asks when the design is not saved)"},
      {"Space", "run / pause the optimization"},
      {"N", "step: let the set number of iterations through"},
      {"R", "reset both views' cameras"},
      {"V", "swap the large and the small view"},
      {"I", "show / hide the small view (the inset)"},
      {"M", "turn the 2D map like the 3D view / keep the map's u across the screen"},
      {"L", "show / hide the lattice"},
      {"B", "show / hide the marks of bare spots (dashed red) and removed stones (grey ghosts)"},
      {"C", "colour by nearest-neighbour ratio / element type"},
      {"Left drag (3D)", "orbit"},
      {"Right or middle drag", "pan"},
      {"Wheel", "zoom"},
      {"Left drag (2D)", "move the pattern over the map (" + key_path(Key::placement_offset) + ")"},
      {"Drag the handles (2D)", "rotate (round) and scale (square) the placement"},
      {"E", "edit stones: clicks in the views select, drag (either view: in 3D start on the stone) and add (Ctrl+click, 2D) single elements"},
      {"Shift+drag (2D, edit stones)", "select every element in a box"},
      {"Del", "delete the selected elements"},
      {"P", "pin the selected elements (they stay where they are while the rest relaxes)"},
      {"Shift+P", "unpin the selected elements (they relax with the rest again)"},
      {"Esc", "deselect"},
      {"Drop a file", "a surface opens, a .json design loads"},
  };
  return list;
}

void handle_shortcuts(Studio& s) {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantTextInput) return;
  const auto pressed = [](int key) { return ImGui::IsKeyPressed(key, false); };
  if (io.KeyCtrl) {
    if (pressed(GLFW_KEY_Z) && !io.KeyShift) undo(s.doc);
    if (pressed(GLFW_KEY_Y) || (pressed(GLFW_KEY_Z) && io.KeyShift)) redo(s.doc);
    if (pressed(GLFW_KEY_S)) {
      const std::string path = s.ui.design_path.empty() ? s.doc.design_path.string() : s.ui.design_path;
      if (path.empty())
        report_status(s.doc, "type a design path in the File panel first");
      else
        save_design_file(s.doc, path);
    }
    if (pressed(GLFW_KEY_E)) {
      try {
        export_outputs(s, s.ui.export_dir);
      } catch (const std::exception& e) {
        report_error(s.doc, e);
      }
    }
    if (pressed(GLFW_KEY_Q)) s.window.request_close();
    return;
  }
  if (pressed(GLFW_KEY_SPACE)) toggle_pause(s);
  if (pressed(GLFW_KEY_N)) step_run(s);
  if (pressed(GLFW_KEY_R) && s.doc.surface.map) frame_views(s);
  if (pressed(GLFW_KEY_V)) swap_views(s);
  if (pressed(GLFW_KEY_I)) {
    s.views.show_inset = !s.views.show_inset;
    fit_views_to_inset(s);
  }
  if (pressed(GLFW_KEY_M)) set_map_follows_3d(s, !s.views.map_follows_3d);
  if (pressed(GLFW_KEY_E)) s.ui.edit_elements = !s.ui.edit_elements;
  if (pressed(GLFW_KEY_ESCAPE)) clear_selection(s.ui);
  if (pressed(GLFW_KEY_DELETE) && s.ui.selected_element >= 0) delete_selected(s);
  // P pins, Shift+P lets go: never a toggle, which un-pinned a stone a drag had pinned and let it
  // slide back. A box follows the clicked element's selection.
  if (pressed(GLFW_KEY_P) && s.ui.selected_element >= 0 && s.doc.result.pavement)
    pin_selected(s, !ImGui::GetIO().KeyShift);
  if (pressed(GLFW_KEY_L)) s.views.style.show_lattice = !s.views.style.show_lattice;
  if (pressed(GLFW_KEY_B)) s.views.show_flaws = !s.views.show_flaws;
  if (pressed(GLFW_KEY_C))
    s.views.colour_mode = s.views.colour_mode == render::ColourMode::NeighbourRatio ? render::ColourMode::ElementType
                                                                                   : render::ColourMode::NeighbourRatio;
}

}  // namespace paver::studio
