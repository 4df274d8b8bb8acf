// The shared renderer, offscreen on lavapipe (any Vulkan device), validation layer on: the images
// show the surface and the elements in the expected colours, and nothing is blank.
#include "io/design_io.h"
#include "mesh/mesh_loader.h"
#include "pipeline/pavement.h"
#include "renderer.h"
#include "report/pavement_quality.h"
#include "surface_maps.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <set>

namespace paver {
namespace {

struct Fixture {
  std::shared_ptr<gpu::VulkanContext> context;
  std::unique_ptr<render::Renderer> renderer;
  std::string why_not;
};

Fixture& fixture() {
  static Fixture f = [] {
    Fixture out;
    gpu::ContextOptions options;
    options.graphics = true;
    options.validation = true;
    auto context = gpu::VulkanContext::create(options);
    if (!context) {
      out.why_not = context.error().message;
      return out;
    }
    auto renderer = render::Renderer::create(context.value());
    if (!renderer) {
      out.why_not = renderer.error().message;
      return out;
    }
    out.context = context.value();
    out.renderer = std::move(renderer.value());
    return out;
  }();
  return f;
}

#define REQUIRE_VULKAN()                                                                                     \
  do {                                                                                                       \
    if (!fixture().renderer) {                                                                               \
      std::fprintf(stderr, "\n*** NO VULKAN DEVICE: the renderer tests are SKIPPED: %s ***\n\n",            \
                   fixture().why_not.c_str());                                                               \
      GTEST_SKIP() << fixture().why_not;                                                                     \
    }                                                                                                        \
  } while (0)

struct Counts {
  int total = 0, background = 0, grey = 0, green = 0, red = 0, blue = 0;
  size_t distinct = 0;
};

Counts count(const render::Image& image) {
  Counts c;
  std::set<std::uint32_t> colours;
  for (size_t i = 0; i + 3 < image.rgba.size(); i += 4) {
    const int r = image.rgba[i], g = image.rgba[i + 1], b = image.rgba[i + 2];
    ++c.total;
    colours.insert(std::uint32_t(r) | std::uint32_t(g) << 8 | std::uint32_t(b) << 16);
    if (std::abs(r - 33) < 4 && std::abs(g - 36) < 4 && std::abs(b - 41) < 4) ++c.background;
    else if (std::abs(r - g) < 12 && std::abs(g - b) < 16 && r > 60) ++c.grey;
    else if (g > r + 30 && g > b + 10) ++c.green;
    else if (r > g + 60 && r > b + 60) ++c.red;
    else if (b > r + 40 && b > g + 10) ++c.blue;
  }
  c.distinct = colours.size();
  return c;
}

const Pavement& dome_pavement(const SurfaceMap& map) {
  static const Pavement p = make_pavement(map, load_design(test::source_dir() / "assets/designs/dome_hex_d6.json"));
  return p;
}

const SurfaceMap& dome_map() { return *test::bundled_map("dome"); }

// The dome's surface and `elements` on it, coloured by `mode`.
void show_on_dome(render::Renderer& r, const Elements& elements, render::ColourMode mode) {
  r.set_surface(dome_map());
  r.set_elements(elements, render::element_colours(elements, mode));
}

TEST(Renderer, PreviewShowsSurfaceAndGreenElements) {
  REQUIRE_VULKAN();
  render::Renderer& r = *fixture().renderer;
  const Pavement& p = dome_pavement(dome_map());
  show_on_dome(r, p.elements, render::ColourMode::NeighbourRatio);
  r.set_pattern(dome_map(), p.pattern, p.points);
  r.render_3d(640, 400, render::frame_surface(dome_map().mesh), {});
  const render::Image image = r.read_back(0);
  ASSERT_EQ(image.width, 640);
  ASSERT_EQ(image.height, 400);
  const Counts c = count(image);
  EXPECT_GT(c.distinct, 500u) << "an image of shaded shapes has many colours";
  EXPECT_GT(c.background, c.total / 20) << "the surface is framed with some background around it";
  EXPECT_GT(c.green, c.total / 10) << "the optimized dome's elements are green (no collisions)";
  EXPECT_LT(c.red, c.total / 200) << "no element is too close";
  render::write_png(::testing::TempDir() + "/preview.png", image);
}

TEST(Renderer, ElementTypeColoursAndHiddenElements) {
  REQUIRE_VULKAN();
  render::Renderer& r = *fixture().renderer;
  const Pavement& p = dome_pavement(dome_map());
  show_on_dome(r, p.elements, render::ColourMode::ElementType);
  render::SceneStyle style;
  r.render_3d(320, 240, render::frame_surface(dome_map().mesh), style);
  const Counts typed = count(r.read_back(0));
  EXPECT_GT(typed.blue, typed.total / 10) << "V-elements are blue";
  style.show_elements = false;
  r.render_3d(320, 240, render::frame_surface(dome_map().mesh), style);
  const Counts bare = count(r.read_back(0));
  EXPECT_EQ(bare.blue, 0);
  EXPECT_GT(bare.grey, bare.total / 5) << "the bare surface is grey";
}

TEST(Renderer, ParameterViewShowsTheMapAndDisks) {
  REQUIRE_VULKAN();
  render::Renderer& r = *fixture().renderer;
  const Pavement& p = dome_pavement(dome_map());
  show_on_dome(r, p.elements, render::ColourMode::NeighbourRatio);
  r.set_pattern(dome_map(), p.pattern, p.points);
  render::SceneStyle style;
  style.show_lattice = true;
  r.render_2d(400, 400, render::frame_map(dome_map()), style);
  const Counts c = count(r.read_back(1));
  EXPECT_GT(c.green, c.total / 10) << "element disks";
  EXPECT_GT(c.background, c.total / 50) << "the map does not fill the whole view";
}

TEST(Renderer, ImagesFollowTheRequestedSize) {
  REQUIRE_VULKAN();
  render::Renderer& r = *fixture().renderer;
  r.set_surface(dome_map());
  r.render_3d(200, 100, render::frame_surface(dome_map().mesh), {});
  const int first = r.image_generation(0);
  r.render_3d(200, 100, render::frame_surface(dome_map().mesh), {});
  EXPECT_EQ(r.image_generation(0), first) << "same size: the image is reused";
  r.render_3d(300, 120, render::frame_surface(dome_map().mesh), {});
  EXPECT_EQ(r.image_generation(0), first + 1) << "new size: the image is re-created";
  const render::Image image = r.read_back(0);
  EXPECT_EQ(image.width, 300);
  EXPECT_EQ(image.height, 120);
  EXPECT_NE(r.image_view(0), nullptr);
  EXPECT_NE(r.sampler(), nullptr);
}

// The studio draws a heavy view a slice per frame: the view keeps its last complete image until
// the new one is whole, and the new one is exactly what a whole render draws.
TEST(Renderer, AnImageDrawnInSlicesIsTheWholeImageAndShownOnlyWhenComplete) {
  REQUIRE_VULKAN();
  render::Renderer& r = *fixture().renderer;
  const Pavement& p = dome_pavement(dome_map());
  // The dome's stones twenty times over (each drawn where it is, so the copies coincide): enough
  // instances for the 2D view's disks to take several slices too.
  Elements many;
  for (int copy = 0; copy < 20; ++copy) many.append(p.elements);
  show_on_dome(r, many, render::ColourMode::NeighbourRatio);
  r.set_pattern(dome_map(), p.pattern, p.points);
  render::SceneStyle style;
  style.show_lattice = true;
  for (const int view : {0, 1}) {
    SCOPED_TRACE(view);
    render::ViewRequest before{480, 300, render::frame_surface(dome_map().mesh), render::frame_map(dome_map()), style};
    render::ViewRequest after = before;
    after.camera.yaw += 0.7f;
    after.map_view.half_height *= 0.6f;
    r.render(view, after);
    const render::Image whole = r.read_back(view);
    r.render(view, before);
    const render::Image old_image = r.read_back(view);
    ASSERT_NE(old_image.rgba, whole.rgba) << "the two requests draw different images";

    const int generation = r.image_generation(view);
    r.start_drawing(view, after);
    int slices = 0;
    bool complete = false;
    while (!complete && slices < 10000) {
      complete = r.draw_more(view, 0.0);  // no budget: one slice per call
      ++slices;
      if (!complete) {
        ASSERT_TRUE(r.drawing(view));
        ASSERT_EQ(r.read_back(view).rgba, old_image.rgba) << "the unfinished image is not shown, slice " << slices;
        ASSERT_EQ(r.image_generation(view), generation);
      }
    }
    ASSERT_TRUE(complete);
    EXPECT_GT(slices, 2) << "thousands of elements take several slices";
    EXPECT_FALSE(r.drawing(view));
    EXPECT_NE(r.image_generation(view), generation) << "the studio binds the new image";
    EXPECT_EQ(r.read_back(view).rgba, whole.rgba) << "drawn in slices, pixel for pixel what a whole render draws";
  }
}

TEST(Renderer, ASceneChangeOrAWholeRenderDropsAnUnfinishedImage) {
  REQUIRE_VULKAN();
  render::Renderer& r = *fixture().renderer;
  const Pavement& p = dome_pavement(dome_map());
  show_on_dome(r, p.elements, render::ColourMode::NeighbourRatio);
  const render::ViewRequest request{320, 200, render::frame_surface(dome_map().mesh), {}, {}};
  r.start_drawing(0, request);
  ASSERT_FALSE(r.draw_more(0, 0.0));
  r.set_elements(p.elements, render::element_colours(p.elements, render::ColourMode::ElementType));
  EXPECT_FALSE(r.drawing(0)) << "its pieces were drawn from the buffers just replaced";
  EXPECT_FALSE(r.draw_more(0, 1e9));
  r.start_drawing(0, request);
  r.render(0, request);
  EXPECT_FALSE(r.drawing(0));
}

// While a heavy view moves the studio shows a quick image: half the size, the surface without the
// elements; the next whole image takes its place again.
TEST(Renderer, AQuickImageIsHalfSizeWithoutTheElementsUntilTheNextWholeOne) {
  REQUIRE_VULKAN();
  render::Renderer& r = *fixture().renderer;
  const Pavement& p = dome_pavement(dome_map());
  show_on_dome(r, p.elements, render::ColourMode::NeighbourRatio);
  const render::ViewRequest request{640, 400, render::frame_surface(dome_map().mesh), {}, {}};
  r.render(0, request);
  const Counts full = count(r.read_back(0));
  ASSERT_GT(full.green, full.total / 10) << "the elements";
  const int generation = r.image_generation(0);
  r.render_quick(0, request);
  EXPECT_NE(r.image_generation(0), generation) << "the studio binds the quick image";
  const render::Image quick = r.read_back(0);
  EXPECT_EQ(quick.width, 320);
  EXPECT_EQ(quick.height, 200);
  const Counts c = count(quick);
  EXPECT_EQ(c.green, 0) << "no elements";
  EXPECT_GT(c.grey, c.total / 5) << "the surface";
  const int quick_generation = r.image_generation(0);
  r.render(0, request);
  EXPECT_NE(r.image_generation(0), quick_generation);
  EXPECT_EQ(r.read_back(0).width, 640);
  EXPECT_GT(count(r.read_back(0)).green, full.total / 10);
}

TEST(Renderer, LegendIsDrawnIntoTheImage) {
  render::Image image;
  image.width = 800, image.height = 600;
  image.rgba.assign(size_t(800) * 600 * 4, 0);
  render::draw_ratio_legend(image);
  const Counts c = count(image);
  EXPECT_GT(c.green, 100);
  EXPECT_GT(c.red, 20);
}

// The 2D view frames the whole map, and beside the studio's inset keeps it in the free part.
TEST(Renderer, TheMapIsFramedWholeAndLeftOfTheInset) {
  const SurfaceMap& map = dome_map();
  for (const double share : {0.0, 0.32}) {
    const double aspect = 1.6;
    const render::MapView v = render::frame_map(map, aspect, share);
    const double half_width = v.half_height * aspect;
    SCOPED_TRACE(share);
    EXPECT_GE(map.uv_min.x, v.centre.x - half_width);
    EXPECT_LE(map.uv_max.x, v.centre.x + half_width * (1 - 2 * share)) << "under the inset";
    EXPECT_GE(map.uv_min.y, v.centre.y - v.half_height);
    EXPECT_LE(map.uv_max.y, v.centre.y + v.half_height);
  }
}

// Every text the PNG legends write has its glyphs (a '+' once drew as a blank).
TEST(Renderer, ThePngLegendsFontHasEveryCharacterTheyWrite) {
  EXPECT_TRUE(render::legend_can_write(render::kRatioLegendTitle)) << render::kRatioLegendTitle;
  for (const char* text : {"point defects", "< 6", "> 6", "0.9", "1.3"}) EXPECT_TRUE(render::legend_can_write(text)) << text;
  for (const auto& entry : render::element_type_legend()) EXPECT_TRUE(render::legend_can_write(entry.label)) << entry.label;
  EXPECT_FALSE(render::legend_can_write("#"));
}

// A PNG's map sits right of its legends: no legend panel pixel lies over the map's extent.
TEST(Renderer, TheMapIsFramedBesideThePngLegends) {
  const SurfaceMap& map = dome_map();
  const int width = 1280, height = 800;
  const double aspect = double(width) / height;
  const double left = double(render::legend_column_width(height)) / width;
  const render::MapView v = render::frame_map(map, aspect, 0, left);
  const double half_width = v.half_height * aspect;
  const auto pixel_x = [&](double u) { return (u - (v.centre.x - half_width)) / (2 * half_width) * width; };
  EXPECT_GE(pixel_x(map.uv_min.x), render::legend_column_width(height)) << "the map runs under the legends";
  EXPECT_LE(pixel_x(map.uv_max.x), width);
  EXPECT_GE(map.uv_min.y, v.centre.y - v.half_height);
  EXPECT_LE(map.uv_max.y, v.centre.y + v.half_height);
  // Every legend panel ends inside that column.
  render::Image image;
  image.width = width, image.height = height;
  image.rgba.assign(size_t(width) * height * 4, 0);
  render::draw_ratio_legend(image);
  render::draw_defect_legend(image, {0, 0, 255}, {255, 0, 255});
  for (int y = 0; y < height; ++y)
    for (int x = render::legend_column_width(height); x < width; ++x)
      ASSERT_EQ(image.rgba[(size_t(y) * width + x) * 4], 0) << "legend pixel at " << x << ", " << y;
}

// The bar is the elements' own colour scale, linear in the ratio, its ticks where their ratios sit.
TEST(Renderer, TheRatioLegendIsTheElementsScaleWithTicksAtTheirRatios) {
  EXPECT_NE(render::ratio_legend_colour(0.9), render::ratio_legend_colour(1.3)) << "red to green";
  // The PNG's bar has, just right of each tick's mark, the colour of the tick's ratio: the bar is
  // linear in the ratio, with the ticks where their ratios sit (the screen draws the same data).
  render::Image image;
  image.width = 800, image.height = 600;
  image.rgba.assign(size_t(800) * 600 * 4, 0);
  render::draw_ratio_legend(image);
  const int scale = 2, bar_w = 260 * scale / 2 + 40, bar_h = 14 * scale;  // legend.cpp's layout at 600 px
  const int x0 = 16 * scale, y0 = image.height - 40 * scale - bar_h;
  for (const double tick : render::ratio_legend_ticks()) {
    const int x = std::min(x0 + int(std::lround(render::ratio_legend_position(tick) * (bar_w - 1))) + 1, x0 + bar_w - 1);
    const std::uint8_t* p = &image.rgba[(std::size_t(y0 + bar_h / 2) * image.width + x) * 4];
    const double r = render::kRatioLegendMin + (render::kRatioLegendMax - render::kRatioLegendMin) * (x - x0) / (bar_w - 1);
    const auto expected = render::ratio_legend_colour(r);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(p[c], expected[c]) << "tick " << tick << " channel " << c;
  }
  const std::vector<double> ticks = render::ratio_legend_ticks();
  ASSERT_GE(ticks.size(), 3u);
  EXPECT_EQ(render::ratio_legend_position(render::kRatioLegendMin), 0.0);
  EXPECT_EQ(render::ratio_legend_position(render::kRatioLegendMax), 1.0);
  EXPECT_NEAR(render::ratio_legend_position(1.1), 0.5, 1e-12) << "linear in the ratio";
  for (double tick : ticks) EXPECT_TRUE(tick >= render::kRatioLegendMin && tick <= render::kRatioLegendMax);
}

TEST(Renderer, TheTypeLegendShowsEveryTypeColour) {
  render::Image image;
  image.width = 800, image.height = 600;
  image.rgba.assign(size_t(800) * 600 * 4, 0);
  render::draw_type_legend(image);
  for (const render::TypeLegendEntry& entry : render::element_type_legend()) {
    long pixels = 0;
    for (size_t i = 0; i < image.rgba.size(); i += 4)
      if (image.rgba[i] == entry.rgb[0] && image.rgba[i + 1] == entry.rgb[1] && image.rgba[i + 2] == entry.rgb[2]) ++pixels;
    EXPECT_GE(pixels, 81) << entry.label << ": its swatch is missing";
  }
}

class NoValidationMessages : public ::testing::Environment {
public:
  void TearDown() override {
    if (!fixture().context) return;
    for (const auto& m : fixture().context->validation_messages()) ADD_FAILURE() << "validation: " << m;
    fixture().renderer.reset();
  }
};
const auto* const kNoValidationMessages = ::testing::AddGlobalTestEnvironment(new NoValidationMessages);

}  // namespace
}  // namespace paver
