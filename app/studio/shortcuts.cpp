#include "pipeline/pavement.h"
#include "shortcuts.h"

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
      {"L", "show / hide the lattice"},
      {"C", "colour by nearest-neighbour ratio / element type"},
      {"Left drag (3D)", "orbit"},
      {"Right or middle drag", "pan"},
      {"Wheel", "zoom"},
      {"Left drag (2D)", "move the pattern over the map (placement.offset)"},
      {"Drag the handles (2D)", "rotate (round) and scale (square) the placement"},
      {"E", "edit stones: clicks in the views select, drag (2D) and add (Ctrl+click, 2D) single elements"},
      {"Del", "delete the selected element"},
      {"P", "pin / unpin the selected element (it stays where it is while the rest relaxes)"},
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
        report_error(s.doc, e.what());
      }
    }
    if (pressed(GLFW_KEY_Q)) s.window.request_close();
    return;
  }
  if (pressed(GLFW_KEY_SPACE)) toggle_pause(s);
  if (pressed(GLFW_KEY_N)) step_run(s);
  if (pressed(GLFW_KEY_R) && s.doc.surface.map) {
    s.views.camera = render::frame_surface(s.doc.surface.map->mesh);
    s.views.map_view = render::frame_map(map_for_topology(*s.doc.surface.map, s.doc.design.pattern.topology), s.views.map_aspect);
  }
  if (pressed(GLFW_KEY_V)) s.views.large_3d = !s.views.large_3d;
  if (pressed(GLFW_KEY_E)) s.ui.edit_elements = !s.ui.edit_elements;
  if (pressed(GLFW_KEY_ESCAPE)) s.ui.selected_element = -1;
  if (pressed(GLFW_KEY_DELETE) && s.ui.selected_element >= 0) delete_selected(s);
  if (pressed(GLFW_KEY_P) && s.ui.selected_element >= 0 && s.doc.result.pavement)
    pin_selected(s, !is_pinned(s.doc.design, *s.doc.result.pavement, s.ui.selected_element));
  if (pressed(GLFW_KEY_L)) s.views.style.show_lattice = !s.views.style.show_lattice;
  if (pressed(GLFW_KEY_C))
    s.views.colour_mode = s.views.colour_mode == render::ColourMode::NeighbourRatio ? render::ColourMode::ElementType
                                                                                   : render::ColourMode::NeighbourRatio;
}

}  // namespace paver::studio
