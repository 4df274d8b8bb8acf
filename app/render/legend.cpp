#include "renderer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

namespace paver::render {
namespace {

// A 5x7 bitmap font with just the characters the legend writes.
const std::map<char, std::array<const char*, 7>>& glyphs() {
  static const std::map<char, std::array<const char*, 7>> font = {
      {'0', {" ### ", "#   #", "#  ##", "# # #", "##  #", "#   #", " ### "}},
      {'1', {"  #  ", " ##  ", "  #  ", "  #  ", "  #  ", "  #  ", " ### "}},
      {'2', {" ### ", "#   #", "    #", "   # ", "  #  ", " #   ", "#####"}},
      {'3', {"#####", "   # ", "  #  ", "   # ", "    #", "#   #", " ### "}},
      {'4', {"   # ", "  ## ", " # # ", "#  # ", "#####", "   # ", "   # "}},
      {'5', {"#####", "#    ", "#### ", "    #", "    #", "#   #", " ### "}},
      {'6', {"  ## ", " #   ", "#    ", "#### ", "#   #", "#   #", " ### "}},
      {'7', {"#####", "    #", "   # ", "  #  ", " #   ", " #   ", " #   "}},
      {'8', {" ### ", "#   #", "#   #", " ### ", "#   #", "#   #", " ### "}},
      {'9', {" ### ", "#   #", "#   #", " ####", "    #", "   # ", " ##  "}},
      {'.', {"     ", "     ", "     ", "     ", "     ", " ##  ", " ##  "}},
      {' ', {"     ", "     ", "     ", "     ", "     ", "     ", "     "}},
      {'/', {"    #", "    #", "   # ", "  #  ", " #   ", "#    ", "#    "}},
      {'<', {"   # ", "  #  ", " #   ", "#    ", " #   ", "  #  ", "   # "}},
      {'>', {" #   ", "  #  ", "   # ", "    #", "   # ", "  #  ", " #   "}},
      {'f', {"  ## ", " #   ", "###  ", " #   ", " #   ", " #   ", " #   "}},
      {'p', {"     ", "     ", "#### ", "#   #", "#   #", "#### ", "#    "}},
      {'N', {"#   #", "##  #", "# # #", "#  ##", "#   #", "#   #", "#   #"}},
      {'a', {"     ", "     ", " ### ", "    #", " ####", "#   #", " ####"}},
      {'c', {"     ", "     ", " ### ", "#    ", "#    ", "#   #", " ### "}},
      {'d', {"    #", "    #", " ## #", "#  ##", "#   #", "#   #", " ####"}},
      {'e', {"     ", "     ", " ### ", "#   #", "#####", "#    ", " ### "}},
      {'i', {"  #  ", "     ", " ##  ", "  #  ", "  #  ", "  #  ", " ### "}},
      {'l', {" ##  ", "  #  ", "  #  ", "  #  ", "  #  ", "  #  ", " ### "}},
      {'m', {"     ", "     ", "## # ", "# # #", "# # #", "#   #", "#   #"}},
      {'n', {"     ", "     ", "# ## ", "##  #", "#   #", "#   #", "#   #"}},
      {'o', {"     ", "     ", " ### ", "#   #", "#   #", "#   #", " ### "}},
      {'r', {"     ", "     ", "# ## ", "##  #", "#    ", "#    ", "#    "}},
      {'s', {"     ", "     ", " ####", "#    ", " ### ", "    #", "#### "}},
      {'t', {" #   ", " #   ", "###  ", " #   ", " #   ", " #  #", "  ## "}},
      {'b', {"#    ", "#    ", "# ## ", "##  #", "#   #", "#   #", "#### "}},
      {'g', {"     ", " ####", "#   #", "#   #", " ####", "    #", " ### "}},
      {'h', {"#    ", "#    ", "# ## ", "##  #", "#   #", "#   #", "#   #"}},
      {'u', {"     ", "     ", "#   #", "#   #", "#   #", "#  ##", " ## #"}},
      {'v', {"     ", "     ", "#   #", "#   #", "#   #", " # # ", "  #  "}},
      {'x', {"     ", "     ", "#   #", " # # ", "  #  ", " # # ", "#   #"}},
      {'E', {"#####", "#    ", "#    ", "#### ", "#    ", "#    ", "#####"}},
      {'V', {"#   #", "#   #", "#   #", "#   #", "#   #", " # # ", "  #  "}},
      {'F', {"#####", "#    ", "#    ", "#### ", "#    ", "#    ", "#    "}},
      {'(', {"   # ", "  #  ", " #   ", " #   ", " #   ", "  #  ", "   # "}},
      {')', {" #   ", "  #  ", "   # ", "   # ", "   # ", "  #  ", " #   "}},
      {'+', {"     ", "  #  ", "  #  ", "#####", "  #  ", "  #  ", "     "}},
  };
  return font;
}

void put(Image& image, int x, int y, std::array<std::uint8_t, 3> rgb) {
  if (x < 0 || y < 0 || x >= image.width || y >= image.height) return;
  std::uint8_t* p = &image.rgba[(std::size_t(y) * image.width + x) * 4];
  p[0] = rgb[0], p[1] = rgb[1], p[2] = rgb[2], p[3] = 255;
}

void text(Image& image, int x, int y, const std::string& s, int scale, std::array<std::uint8_t, 3> rgb) {
  for (char ch : s) {
    const auto it = glyphs().find(ch);
    if (it != glyphs().end())
      for (int row = 0; row < 7; ++row)
        for (int col = 0; col < 5; ++col)
          if (it->second[row][col] == '#')
            for (int dy = 0; dy < scale; ++dy)
              for (int dx = 0; dx < scale; ++dx) put(image, x + col * scale + dx, y + row * scale + dy, rgb);
    x += 6 * scale;
  }
}

}  // namespace

namespace {
struct RatioLegendBox {
  int scale, bar_w, bar_h, x0, panel_w;
};
RatioLegendBox ratio_legend_box(int image_height) {
  const int scale = image_height >= 600 ? 2 : 1;
  const int bar_w = 260 * scale / 2 + 40;
  return {scale, bar_w, 14 * scale, 16 * scale, std::max(bar_w, int(std::string(kRatioLegendTitle).size()) * 6 * scale)};
}
}  // namespace

bool legend_can_write(std::string_view text) {
  return std::all_of(text.begin(), text.end(), [](char ch) { return glyphs().count(ch) > 0; });
}

int legend_column_width(int image_height) {
  const RatioLegendBox box = ratio_legend_box(image_height);
  return box.x0 + box.panel_w + 16 * box.scale;  // the widest legend's panel and a margin
}

void draw_ratio_legend(Image& image) {
  const auto [scale, bar_w, bar_h, x0, panel_w] = ratio_legend_box(image.height);
  const int y0 = image.height - 40 * scale - bar_h;
  const std::string title = kRatioLegendTitle;
  // Panel behind the legend so it reads on any background.
  for (int y = y0 - 22 * scale; y < y0 + bar_h + 22 * scale; ++y)
    for (int x = x0 - 8 * scale; x < x0 + panel_w + 8 * scale; ++x) put(image, x, y, {28, 30, 34});
  for (int x = 0; x < bar_w; ++x) {
    const double r = kRatioLegendMin + (kRatioLegendMax - kRatioLegendMin) * x / (bar_w - 1);
    const std::array<std::uint8_t, 3> c = ratio_legend_colour(r);
    for (int y = 0; y < bar_h; ++y) put(image, x0 + x, y0 + y, c);
  }
  const std::array<std::uint8_t, 3> white{235, 235, 235};
  text(image, x0, y0 - 12 * scale, title, scale, white);
  for (const double tick : ratio_legend_ticks()) {
    const int x = x0 + int(std::lround(ratio_legend_position(tick) * (bar_w - 1)));
    for (int y = 0; y < 4 * scale; ++y) put(image, x, y0 + bar_h + y, white);
    char label[16];
    std::snprintf(label, sizeof label, "%.1f", tick);
    text(image, x - 8 * scale, y0 + bar_h + 6 * scale, label, scale, white);
  }
}

void draw_type_legend(Image& image) {
  const int scale = image.height >= 600 ? 2 : 1;
  const std::vector<TypeLegendEntry> entries = element_type_legend();
  const int rows = int(entries.size());
  const int x0 = 16 * scale, y0 = image.height - (16 + 14 * rows) * scale;
  for (int y = y0 - 8 * scale; y < y0 + 14 * rows * scale; ++y)
    for (int x = x0 - 8 * scale; x < x0 + 130 * scale; ++x) put(image, x, y, {28, 30, 34});
  const std::array<std::uint8_t, 3> white{235, 235, 235};
  int row = y0;
  for (const TypeLegendEntry& entry : entries) {
    for (int y = 0; y < 9 * scale; ++y)
      for (int x = 0; x < 9 * scale; ++x) put(image, x0 + x, row + y, entry.rgb);
    text(image, x0 + 16 * scale, row + scale, entry.label, scale, white);
    row += 14 * scale;
  }
}

void draw_defect_legend(Image& image, std::array<std::uint8_t, 3> fewer, std::array<std::uint8_t, 3> more) {
  const int scale = image.height >= 600 ? 2 : 1;
  // Above the ratio legend (draw_ratio_legend), which the same picture carries for the other stones.
  const int x0 = 16 * scale, y0 = image.height - 140 * scale;
  for (int y = y0 - 8 * scale; y < y0 + 48 * scale; ++y)
    for (int x = x0 - 8 * scale; x < x0 + 110 * scale; ++x) put(image, x, y, {28, 30, 34});
  const std::array<std::uint8_t, 3> white{235, 235, 235};
  text(image, x0, y0, "point defects", scale, white);
  int row = y0 + 14 * scale;
  for (const auto& [rgb, label] : {std::pair{fewer, "< 6"}, std::pair{more, "> 6"}}) {
    for (int y = 0; y < 9 * scale; ++y)
      for (int x = 0; x < 9 * scale; ++x) put(image, x0 + x, row + y, rgb);
    text(image, x0 + 16 * scale, row + scale, label, scale, white);
    row += 14 * scale;
  }
}

}  // namespace paver::render
