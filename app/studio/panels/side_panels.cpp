#include "panels.h"

#include "../studio.h"

#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>

namespace paver::studio {

void help_marker(const char* text) {
  ImGui::SameLine();
  ImGui::TextDisabled("(?)");
  if (ImGui::IsItemHovered()) {
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30);
    ImGui::TextUnformatted(text);
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
  }
}

bool typed_number(const char* label, double& value, const char* format) {
  // What is being typed, per field, while it has the focus: ImGui writes it on every keystroke,
  // and the design only takes it when the field lets go (Enter, Tab or a click elsewhere). What the
  // field showed when it took the focus is kept too: Escape restores that text, rounded by
  // `format`, and that is no change.
  struct Typing {
    double shown, typed;
  };
  static std::map<ImGuiID, Typing> typing;
  const ImGuiID id = ImGui::GetID(label);
  const auto it = typing.find(id);
  double typed = it != typing.end() ? it->second.typed : value;
  ImGui::InputDouble(label, &typed, 0, 0, format);
  if (ImGui::IsItemActive()) {
    if (it == typing.end()) {
      char text[64];
      std::snprintf(text, sizeof text, format, value);
      typing[id] = {std::strtod(text, nullptr), typed};
    } else {
      it->second.typed = typed;
    }
    return false;
  }
  const double shown = it != typing.end() ? it->second.shown : value;
  if (it != typing.end()) typing.erase(it);
  if (!ImGui::IsItemDeactivatedAfterEdit() || typed == shown || typed == value) return false;
  value = typed;
  return true;
}

void section(const char* title) {
  ImGui::Spacing();
  ImGui::Separator();
  ImGui::TextUnformatted(title);
}

void side_panels(Studio& s, ImVec2 pos, ImVec2 size) {
  ImGui::SetNextWindowPos(pos);
  ImGui::SetNextWindowSize(size);
  ImGui::Begin("Paver Studio", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_NoBringToFrontOnFocus);
  if (ImGui::BeginTabBar("panels")) {
    // Tab labels are the panel names capitalised ("optimize" -> "Optimize").
    const auto tab = [&](const char* name, auto&& draw) {
      std::string key(name);
      key[0] = char(std::tolower(static_cast<unsigned char>(key[0])));
      const ImGuiTabItemFlags flags = s.ui.select_panel == key ? ImGuiTabItemFlags_SetSelected : 0;
      if (ImGui::BeginTabItem(name, nullptr, flags)) {
        draw();
        ImGui::EndTabItem();
      }
    };
    tab("File", [&] { file_panel(s); });
    tab("Pattern", [&] { pattern_panel(s.doc, s.ui); });
    tab("Elements", [&] {
      elements_panel(s.doc, s.ui);
      single_elements_panel(s);
    });
    tab("Optimize", [&] { optimization_panel(s); });
    tab("Report", [&] { report_panel(s); });
    tab("Help", [] { help_panel(); });
    s.ui.select_panel.clear();
    ImGui::EndTabBar();
  }
  ImGui::End();
}

}  // namespace paver::studio
