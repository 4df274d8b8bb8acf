// The file dialog (file_browser.h drawn): a folder's files of the kind asked for, folders first;
// double-click a folder to enter it, a file to choose it; Save as asks before it replaces a file.
#include "panels.h"

#include "../studio.h"

#include <imgui_stdlib.h>

#include <cstdio>
#include <filesystem>

namespace paver::studio {
namespace {

namespace fs = std::filesystem;

std::string size_text(std::uintmax_t bytes) {
  char text[32];
  if (bytes >= 1u << 20)
    std::snprintf(text, sizeof text, "%.1f MB", double(bytes) / (1u << 20));
  else
    std::snprintf(text, sizeof text, "%.1f kB", double(bytes) / 1024);
  return text;
}

// What OK does with the path chosen, by the purpose the dialog was opened for.
void use_path(Studio& s, const fs::path& path) {
  UiState& ui = s.ui;
  switch (ui.browser.purpose) {
    case BrowsePurpose::OpenSurface:
      ui.surface_path = path.string();
      open_surface(s, path);
      break;
    case BrowsePurpose::LoadDesign: open_any(s, path); break;
    case BrowsePurpose::SaveDesign: {
      std::error_code error;
      // Replacing the design's own file is what Save does; any other file is asked about first
      // (a bundled design or an input is refused outright, without asking).
      const bool own = !s.doc.design_path.empty() && fs::equivalent(path, s.doc.design_path, error);
      if (fs::exists(path, error) && !own && !is_bundled_design(path))
        ui.confirm_replace = path;
      else
        save_design_as(s, path);
      break;
    }
    case BrowsePurpose::ExportFolder: ui.export_dir = path.string(); break;
    case BrowsePurpose::CustomShape: ui.custom_shape_path = path.string(); break;
  }
}

void replace_question(Studio& s) {
  if (s.ui.confirm_replace && !ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId)) ImGui::OpenPopup("Replace file");
  ImGui::SetNextWindowSize(ImVec2(460, 0));
  if (!ImGui::BeginPopupModal("Replace file", nullptr, ImGuiWindowFlags_NoSavedSettings)) return;
  ImGui::TextWrapped("%s already exists. Replace it with this design?", s.ui.confirm_replace->string().c_str());
  if (ImGui::Button("Replace", ImVec2(120, 0))) {
    save_design_as(s, *s.ui.confirm_replace);
    s.ui.confirm_replace.reset();
    ImGui::CloseCurrentPopup();
  }
  ImGui::SameLine();
  if (ImGui::Button("Cancel", ImVec2(120, 0)) || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) {
    s.ui.confirm_replace.reset();
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

}  // namespace

void file_dialog(Studio& s) {
  FileBrowser& b = s.ui.browser;
  const char* title = browse_title(b.purpose);
  if (b.open && !ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId)) ImGui::OpenPopup(title);
  const ImVec2 screen = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowSize(ImVec2(std::min(640.0f, screen.x * 0.9f), std::min(480.0f, screen.y * 0.8f)),
                           ImGuiCond_Appearing);
  if (ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_NoSavedSettings)) {
    std::optional<fs::path> chosen;
    const auto close = [&] {
      b.open = false;
      ImGui::CloseCurrentPopup();
    };
    if (ImGui::Button("Up")) show_parent_folder(b);
    ImGui::SameLine();
    std::string folder = b.folder.string();
    ImGui::SetNextItemWidth(-1);
    if (ImGui::InputText("##folder", &folder, ImGuiInputTextFlags_EnterReturnsTrue)) show_folder(b, folder);
    const bool folders_only = b.purpose == BrowsePurpose::ExportFolder;
    const float footer = ImGui::GetFrameHeightWithSpacing() * 3;
    ImGui::BeginChild("entries", ImVec2(0, -footer), true);
    for (const BrowserEntry& entry : std::vector<BrowserEntry>(b.entries)) {  // entering a folder relists
      const std::string label = (entry.folder ? "[folder] " : "") + entry.name;
      const bool selected = !entry.folder && entry.name == b.name;
      if (ImGui::Selectable(label.c_str(), selected, ImGuiSelectableFlags_AllowDoubleClick)) {
        if (!entry.folder) b.name = entry.name;
        if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) chosen = activate(b, entry);
      }
      if (!entry.folder) {
        ImGui::SameLine(ImGui::GetWindowContentRegionMax().x - ImGui::CalcTextSize("0000.0 MB").x);
        ImGui::TextDisabled("%s", size_text(entry.bytes).c_str());
      }
    }
    if (b.entries.empty()) ImGui::TextDisabled(folders_only ? "no folders here" : "no files of this kind here");
    ImGui::EndChild();
    ImGui::SetNextItemWidth(-1);
    if (ImGui::InputTextWithHint("##name", folders_only ? "a new folder inside (optional)" : "file name", &b.name,
                                 ImGuiInputTextFlags_EnterReturnsTrue))
      chosen = chosen_path(b);
    if (!b.problem.empty()) ImGui::TextColored(ImVec4(1, 0.45f, 0.4f, 1), "%s", b.problem.c_str());
    if (ImGui::Button(b.purpose == BrowsePurpose::SaveDesign ? "Save" : "OK", ImVec2(120, 0))) chosen = chosen_path(b);
    ImGui::SameLine();
    if (ImGui::Checkbox("hidden files", &b.show_hidden)) show_folder(b, ".");
    ImGui::SameLine(ImGui::GetWindowContentRegionMax().x - 120);
    if (ImGui::Button("Cancel", ImVec2(120, 0)) || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) close();
    if (chosen) {
      close();
      use_path(s, *chosen);
    }
    ImGui::EndPopup();
  }
  replace_question(s);
}

}  // namespace paver::studio
