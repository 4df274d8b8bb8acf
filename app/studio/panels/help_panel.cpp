// The help panel: what the studio does, and the keyboard and mouse shortcuts.
#include "panels.h"

#include "../shortcuts.h"

namespace paver::studio {

void help_panel() {
  ImGui::TextWrapped("Paver paves a surface with elements in a regular pattern: open a surface, design the "
                     "pattern and the elements, and the optimizer (section 5) makes it regular and "
                     "collision-free. Every change re-runs it; the views show it moving.");
  section("Shortcuts");
  if (ImGui::BeginTable("shortcuts", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) {
    for (const Shortcut& shortcut : shortcut_list()) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(shortcut.keys);
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(shortcut.action);
    }
    ImGui::EndTable();
  }
}

}  // namespace paver::studio
