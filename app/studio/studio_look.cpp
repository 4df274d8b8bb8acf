#include "studio_look.h"

#include <imgui.h>

#include <filesystem>

namespace paver::studio {
namespace {

constexpr float kFontPixels = 15.0f;

ImVec4 rgb(int r, int g, int b, float a = 1.0f) { return ImVec4(r / 255.0f, g / 255.0f, b / 255.0f, a); }

void graphite_theme(ImGuiStyle& style) {
  ImGui::StyleColorsDark(&style);
  style.WindowRounding = 0;
  style.FrameRounding = 3;
  style.GrabRounding = 3;
  style.TabRounding = 3;
  style.ScrollbarRounding = 3;
  style.FrameBorderSize = 1;
  style.WindowBorderSize = 1;
  style.FramePadding = ImVec2(6, 4);
  style.ItemSpacing = ImVec2(8, 5);
  style.ItemInnerSpacing = ImVec2(6, 4);
  style.IndentSpacing = 16;
  style.ScrollbarSize = 13;
  ImVec4* c = style.Colors;
  const ImVec4 accent = rgb(66, 133, 214), accent_hover = rgb(92, 156, 232), accent_active = rgb(48, 112, 190);
  c[ImGuiCol_Text] = rgb(228, 230, 235);
  c[ImGuiCol_TextDisabled] = rgb(150, 155, 165);
  c[ImGuiCol_WindowBg] = rgb(32, 34, 38);
  c[ImGuiCol_ChildBg] = rgb(28, 30, 34);
  c[ImGuiCol_PopupBg] = rgb(38, 40, 45, 0.98f);
  c[ImGuiCol_Border] = rgb(62, 66, 74);
  c[ImGuiCol_FrameBg] = rgb(46, 49, 55);
  c[ImGuiCol_FrameBgHovered] = rgb(58, 62, 70);
  c[ImGuiCol_FrameBgActive] = rgb(66, 71, 80);
  c[ImGuiCol_TitleBg] = rgb(28, 30, 34);
  c[ImGuiCol_TitleBgActive] = rgb(36, 39, 44);
  c[ImGuiCol_CheckMark] = accent_hover;
  c[ImGuiCol_SliderGrab] = accent;
  c[ImGuiCol_SliderGrabActive] = accent_hover;
  c[ImGuiCol_Button] = rgb(54, 58, 66);
  c[ImGuiCol_ButtonHovered] = rgb(70, 76, 86);
  c[ImGuiCol_ButtonActive] = accent_active;
  c[ImGuiCol_Header] = rgb(52, 56, 64);
  c[ImGuiCol_HeaderHovered] = rgb(64, 70, 80);
  c[ImGuiCol_HeaderActive] = accent_active;
  c[ImGuiCol_Separator] = rgb(62, 66, 74);
  c[ImGuiCol_SeparatorHovered] = accent_hover;
  c[ImGuiCol_SeparatorActive] = accent;
  c[ImGuiCol_Tab] = rgb(42, 45, 51);
  c[ImGuiCol_TabHovered] = accent_hover;
  c[ImGuiCol_TabActive] = accent;
  c[ImGuiCol_TabUnfocused] = rgb(42, 45, 51);
  c[ImGuiCol_TabUnfocusedActive] = rgb(54, 86, 128);
  c[ImGuiCol_TableHeaderBg] = rgb(44, 47, 53);
  c[ImGuiCol_TableBorderStrong] = rgb(62, 66, 74);
  c[ImGuiCol_TableBorderLight] = rgb(50, 53, 60);
  c[ImGuiCol_TableRowBgAlt] = rgb(255, 255, 255, 0.03f);
  c[ImGuiCol_TextSelectedBg] = rgb(66, 133, 214, 0.40f);
  c[ImGuiCol_NavHighlight] = accent;
}

}  // namespace

const char* studio_font_path() {
  static const char* const kPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
  std::error_code ignored;
  return std::filesystem::is_regular_file(kPath, ignored) ? kPath : "";
}

bool apply_studio_look() {
  graphite_theme(ImGui::GetStyle());
  const char* path = studio_font_path();
  if (!*path) return false;
  ImGuiIO& io = ImGui::GetIO();
  // Latin with its accents (file names, "pavé"), Greek (the paper's symbols) and the signs used.
  static const ImWchar kRanges[] = {0x0020, 0x024F, 0x0370, 0x03FF, 0x2000, 0x22FF, 0};
  return io.Fonts->AddFontFromFileTTF(path, kFontPixels, nullptr, kRanges) != nullptr;
}

}  // namespace paver::studio
