// The studio's look (issue 45: the stock ImGui theme and monospace font looked like a research
// tool): the proportional font is loaded where the set-up installs it, and the theme is not
// ImGui's stock dark one.
#include "studio_look.h"

#include <gtest/gtest.h>
#include <imgui.h>

#include <cmath>
#include <string>

namespace paver::studio {
namespace {

TEST(StudioLook, DejaVuSansAndTheGraphiteTheme) {
  ImGui::CreateContext();
  ImGuiStyle stock;
  ImGui::StyleColorsDark(&stock);
  const bool loaded = apply_studio_look();
  const std::string path = studio_font_path();
  if (path.empty()) {
    EXPECT_FALSE(loaded);
    ADD_FAILURE() << "DejaVu Sans is not installed: app/setup.sh installs fonts-dejavu-core";
  } else {
    EXPECT_TRUE(loaded);
    ImFontAtlas& fonts = *ImGui::GetIO().Fonts;
    ASSERT_EQ(fonts.ConfigData.Size, 1);
    EXPECT_NE(std::string(fonts.ConfigData[0].Name).find("DejaVuSans.ttf"), std::string::npos) << fonts.ConfigData[0].Name;
    EXPECT_TRUE(fonts.Build());
    // Proportional: an "i" is narrower than an "m".
    const ImFont* font = fonts.Fonts[0];
    EXPECT_LT(font->CalcTextSizeA(font->FontSize, 1e9f, 0, "iiii").x, font->CalcTextSizeA(font->FontSize, 1e9f, 0, "mmmm").x);
  }
  const ImGuiStyle& style = ImGui::GetStyle();
  EXPECT_GT(style.FrameRounding, 0) << "rounded frames";
  EXPECT_NE(style.Colors[ImGuiCol_WindowBg].x, stock.Colors[ImGuiCol_WindowBg].x) << "not the stock theme";
  // Text stands out from the fields it is typed into: a luminance ratio of at least 7 (WCAG AAA).
  const auto linear = [](float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); };
  const auto luminance = [&](const ImVec4& c) { return 0.2126f * linear(c.x) + 0.7152f * linear(c.y) + 0.0722f * linear(c.z); };
  EXPECT_GT((luminance(style.Colors[ImGuiCol_Text]) + 0.05f) / (luminance(style.Colors[ImGuiCol_FrameBg]) + 0.05f), 7.0f);
  ImGui::DestroyContext();
}

}  // namespace
}  // namespace paver::studio
