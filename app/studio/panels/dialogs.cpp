// The status line, the error dialog (errors never end the session and never touch the design)
// and the question asked before quitting with unsaved design changes.
#include "panels.h"

#include "../studio.h"

#include <imgui_stdlib.h>

namespace paver::studio {

void status_bar(Studio& s, ImVec2 pos, ImVec2 size) {
  ImGui::SetNextWindowPos(pos);
  ImGui::SetNextWindowSize(size);
  ImGui::Begin("##status", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                        ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoScrollbar);
  const RunState state = s.live.state();
  if (s.loader.busy())
    ImGui::Text("[%s %.0f%%]", s.loader.stage().c_str(), 100 * s.loader.progress());
  else if (state == RunState::Running || state == RunState::Paused)
    ImGui::Text("[%s: iteration %d]", state == RunState::Running ? "optimizing" : "paused", s.live.iteration());
  else if (result_is_final(s) && s.doc.result.latency_ms >= 0)
    ImGui::Text("[final, %.0f ms from the edit]", s.doc.result.latency_ms);
  else if (result_is_final(s))
    ImGui::TextUnformatted("[final]");
  else
    ImGui::TextUnformatted("[ ]");
  ImGui::SameLine();
  if (s.doc.dirty) {
    ImGui::TextColored(ImVec4(1, 0.8f, 0.3f, 1), "unsaved");
    ImGui::SameLine();
  }
  const std::string& status = s.doc.messages.status;
  const bool error = status.starts_with("error:") || status.starts_with("refused:") || status.starts_with("NOT OK");
  // A pavement that is ok but leaves bare spots or removed stones: amber, as a thing to look at.
  const bool notice = status.starts_with("ok:") && status.find("(marked in the views)") != std::string::npos;
  if (notice) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 0.78f, 0.3f, 1));
  if (error) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 0.45f, 0.4f, 1));
  ImGui::PushTextWrapPos(0);
  ImGui::TextUnformatted(s.doc.messages.status.c_str());
  ImGui::PopTextWrapPos();
  if (error || notice) ImGui::PopStyleColor();
  ImGui::End();
}

void dialogs(Studio& s) {
  Document& doc = s.doc;
  // One modal at a time: opening one while another is up makes them close each other every frame.
  if (!doc.messages.error.empty() && !ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId)) ImGui::OpenPopup("Error");
  ImGui::SetNextWindowSize(ImVec2(520, 0));
  if (ImGui::BeginPopupModal("Error", nullptr, ImGuiWindowFlags_NoSavedSettings)) {
    ImGui::TextWrapped("%s", doc.messages.error.c_str());
    ImGui::Spacing();
    ImGui::TextDisabled("%s", doc.messages.error_kept_design
                                  ? "The design is unchanged."
                                  : "The views keep the last pavement that could be made; Ctrl+Z undoes the last change.");
    // Closed by OK, or when a newer run has made the error stale (mark_run_started).
    if (ImGui::Button("OK", ImVec2(120, 0)) || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter)) ||
        doc.messages.error.empty()) {
      doc.messages.error.clear();
      ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
  }

  // A design above the run budget: run it anyway, or go back.
  const bool over_budget = !s.script_mode && s.run.budget_asked == doc.revision && s.run.budget_granted != doc.revision;
  if (over_budget && doc.messages.error.empty() && !ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId))
    ImGui::OpenPopup("Large design");
  ImGui::SetNextWindowSize(ImVec2(520, 0));
  if (ImGui::BeginPopupModal("Large design", nullptr, ImGuiWindowFlags_NoSavedSettings)) {
    ImGui::TextWrapped("This design would place about %s. The studio stays responsive and the Solver panel's "
                       "Reset ends the run, but the views will be slow.",
                       large_design_text(s.run.budget_points, s.run.point_budget).c_str());
    if (ImGui::Button("Run anyway", ImVec2(140, 0))) {
      ImGui::CloseCurrentPopup();
      grant_budget(s);
    }
    ImGui::SameLine();
    if (ImGui::Button("Go back", ImVec2(140, 0)) || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) {
      ImGui::CloseCurrentPopup();
      decline_budget(s);
    }
    ImGui::EndPopup();
  }

  if (s.ui.quit_dialog && doc.messages.error.empty() && !ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId)) {
    ImGui::OpenPopup("Quit");
    // A bundled design cannot be saved over: offer a name of the user's own (save_as_start), as the
    // file browser does, rather than a path that Save then refuses.
    if (s.ui.design_path.empty() || is_bundled_design(s.ui.design_path))
      s.ui.design_path = doc.design_path.empty() ? std::string("my_design.json") : save_as_start(doc.design_path).string();
  }
  ImGui::SetNextWindowSize(ImVec2(460, 0));
  if (ImGui::BeginPopupModal("Quit", nullptr, ImGuiWindowFlags_NoSavedSettings)) {
    ImGui::TextWrapped("The design has changes that are not saved.");
    ImGui::InputText("design file", &s.ui.design_path);
    const auto close = [&](bool quit) {
      s.ui.quit_dialog = false;
      s.quit = quit;
      s.ui.quit_message.clear();
      ImGui::CloseCurrentPopup();
    };
    if (ImGui::Button("Save", ImVec2(120, 0))) {
      // Said here: the error dialog cannot open over this one.
      if (s.ui.design_path.empty()) s.ui.quit_message = "give the design a file name to save it to";
      else if (save_design_file(doc, s.ui.design_path)) close(true);
      else s.ui.quit_message = doc.messages.error, doc.messages.error.clear();
    }
    ImGui::SameLine();
    if (ImGui::Button("Discard", ImVec2(120, 0))) close(true);
    ImGui::SameLine();
    if (ImGui::Button("Cancel", ImVec2(120, 0)) || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) close(false);
    if (!s.ui.quit_message.empty()) {
      ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 0.45f, 0.4f, 1));
      ImGui::TextWrapped("%s", s.ui.quit_message.c_str());
      ImGui::PopStyleColor();
    }
    ImGui::EndPopup();
  }
}

}  // namespace paver::studio
