#include "panels.h"

#include "../studio.h"
#include "../number_rules.h"

#include <imgui_stdlib.h>

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

bool typed_number(const char* label, double& value, const char* format, const NumberRule& rule) {
  // Per field: the text while it is typed (the design takes it only when the field lets go: Enter,
  // Tab or a click elsewhere), and a refused text with its reason, kept on screen until the field
  // takes a value or the value changes under it (an undo). Escape restores what was shown.
  struct Field {
    std::string text, shown, problem;
    double value_when_refused = 0;
    bool active = false;  // being typed into
  };
  static std::map<ImGuiID, Field> fields;
  const ImGuiID id = ImGui::GetID(label);
  char shown_text[64];
  std::snprintf(shown_text, sizeof shown_text, format, value);
  Field& field = fields[id];
  if (!field.problem.empty() && value != field.value_when_refused) field = {};
  if (field.problem.empty() && !field.active) field.text = field.shown = shown_text;
  const bool refused = !field.problem.empty();
  if (refused) {
    ImGui::PushStyleColor(ImGuiCol_Border, ImVec4(1, 0.35f, 0.3f, 1));
    ImGui::PushStyleVar(ImGuiStyleVar_FrameBorderSize, 2);
  }
  ImGui::InputText(label, &field.text, ImGuiInputTextFlags_AutoSelectAll);
  if (refused) {
    ImGui::PopStyleVar();
    ImGui::PopStyleColor();
  }
  remember_field_place(label);
  field.active = ImGui::IsItemActive();
  bool changed = false;
  if (ImGui::IsItemDeactivated()) {
    if (field.text == field.shown) {
      field = {};  // nothing typed, or Escape
    } else {
      // The label as the designer reads it: what precedes "##".
      const std::string_view name = std::string_view(label).substr(0, std::string_view(label).find("##"));
      const TypedNumber typed = read_typed_number(name, field.text, rule);
      if (!typed.value) {
        field.problem = typed.problem;
        field.value_when_refused = value;
        post_refusal(typed.problem);
      } else {
        changed = *typed.value != value;
        value = *typed.value;
        field = {};
      }
    }
  }
  if (!field.problem.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 0.45f, 0.4f, 1));
    ImGui::PushTextWrapPos(0);
    ImGui::TextUnformatted(field.problem.c_str());
    ImGui::PopTextWrapPos();
    ImGui::PopStyleColor();
  }
  return changed;
}

namespace {
struct FieldPlace {
  ImVec2 min, max;
  int frame = -1;
  int active_frame = -1;  // the last frame it had the keyboard
};
std::map<std::string, FieldPlace, std::less<>>& field_places() {
  static std::map<std::string, FieldPlace, std::less<>> places;
  return places;
}
}  // namespace

void remember_field_place(const char* label) {
  const std::string_view full(label);
  const std::string shown(full.substr(0, full.find("##")));
  // The item's rectangle holds the label on its right: the place to click is the box left of it.
  ImVec2 box_max = ImGui::GetItemRectMax();
  if (!shown.empty()) box_max.x -= ImGui::CalcTextSize(shown.c_str()).x + ImGui::GetStyle().ItemInnerSpacing.x;
  FieldPlace& place = field_places()[shown];
  place.min = ImGui::GetItemRectMin(), place.max = box_max, place.frame = ImGui::GetFrameCount();
  if (ImGui::IsItemActive()) place.active_frame = place.frame;
}

bool field_was_active_since(std::string_view label, int frame) {
  const auto it = field_places().find(label);
  return it != field_places().end() && it->second.active_frame >= frame;
}

std::optional<glm::vec2> field_centre(std::string_view label) {
  const auto it = field_places().find(label);
  // Drawn this frame or the last: a field of a panel not shown is not there to click.
  if (it == field_places().end() || it->second.frame < ImGui::GetFrameCount() - 1) return std::nullopt;
  return glm::vec2(0.5f * (it->second.min.x + it->second.max.x), 0.5f * (it->second.min.y + it->second.max.y));
}

void section(const char* title) {
  ImGui::Spacing();
  ImGui::Separator();
  ImGui::TextUnformatted(title);
}

void panel_splitter(Studio& s, ImVec2 pos, float height) {
  // ImGui 1.86 has no docking: a thin window over the panels' edge that a drag moves.
  ImGui::SetNextWindowPos(pos);
  ImGui::SetNextWindowSize(ImVec2(6, height));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
  ImGui::Begin("##splitter", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoBackground |
                   ImGuiWindowFlags_NoSavedSettings);
  ImGui::PopStyleVar();
  ImGui::InvisibleButton("split", ImVec2(6, height));
  const bool hot = ImGui::IsItemHovered() || ImGui::IsItemActive();
  if (hot) ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeEW);
  if (ImGui::IsItemActive()) s.views.side_width = pos.x + 3 + ImGui::GetIO().MouseDelta.x;
  if (hot)
    ImGui::GetWindowDrawList()->AddRectFilled(ImVec2(pos.x + 2, pos.y), ImVec2(pos.x + 4, pos.y + height),
                                              ImGui::GetColorU32(ImGuiCol_SeparatorHovered));
  ImGui::End();
}

void side_panels(Studio& s, ImVec2 pos, ImVec2 size) {
  ImGui::SetNextWindowPos(pos);
  ImGui::SetNextWindowSize(size);
  ImGui::Begin("Paver Studio", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_NoBringToFrontOnFocus);
  // Fields leave room for their labels in words ("rotation (degrees)", "rows along axis"): none clipped.
  ImGui::PushItemWidth(-ImGui::GetFontSize() * 10.5f);
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
  ImGui::PopItemWidth();
  ImGui::End();
}

}  // namespace paver::studio
