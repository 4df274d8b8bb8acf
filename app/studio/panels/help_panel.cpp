// The help panel: what the studio does, and the keyboard and mouse shortcuts.
#include "panels.h"

#include "../shortcuts.h"

namespace paver::studio {

void help_panel() {
  ImGui::TextWrapped("Paver paves a surface with elements in a regular pattern: open a surface, design the "
                     "pattern and the elements, and the optimizer (section 5) makes it regular and "
                     "collision-free. Every change re-runs it; the views show it moving.");
  section("Shortcuts");
  // Both columns wrap inside the side panel (a long action used to run off its edge).
  if (ImGui::BeginTable("shortcuts", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp)) {
    ImGui::TableSetupColumn("keys", ImGuiTableColumnFlags_WidthStretch, 0.35f);
    ImGui::TableSetupColumn("action", ImGuiTableColumnFlags_WidthStretch, 0.65f);
    for (const Shortcut& shortcut : shortcut_list()) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextWrapped("%s", shortcut.keys);
      ImGui::TableNextColumn();
      ImGui::TextWrapped("%s", shortcut.action.c_str());
    }
    ImGui::EndTable();
  }
}

}  // namespace paver::studio
