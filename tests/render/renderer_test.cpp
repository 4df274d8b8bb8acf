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

#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
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

// --- the 2D map turned like the 3D view ---------------------------------------------------------

// The median angle, in degrees, between each front-facing edge's image in the 3D view and its
// image in the 2D view `v`: measured edge by edge, apart from the fit that chose the turn.
double median_edge_angle_deg(const SurfaceMap& map, const render::OrbitCamera& camera, const render::MapView& v,
                             double aspect) {
  const glm::dmat4 vp = glm::dmat4(camera.view_projection(float(aspect)));
  const auto screen = [&](glm::dvec3 p) {
    const glm::dvec4 c = vp * glm::dvec4(p, 1);
    return glm::dvec2(c.x / c.w * aspect, c.y / c.w);
  };
  std::vector<double> angles;
  for (const glm::ivec3& t : map.mesh.triangles) {
    const glm::dvec2 a = screen(map.mesh.positions[t.x]), b = screen(map.mesh.positions[t.y]),
                     c = screen(map.mesh.positions[t.z]);
    if ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x) <= 0) continue;  // faces away
    glm::dvec2 along_map = map.uv[t.y] - map.uv[t.x];
    if (map.period > 0) along_map.x -= map.period * std::round(along_map.x / map.period);
    const glm::dvec2 in_2d = v.screen_offset(glm::dvec2(v.centre) + along_map), in_3d = b - a;
    const double angle = std::atan2(in_2d.x * in_3d.y - in_2d.y * in_3d.x, glm::dot(in_2d, in_3d));
    angles.push_back(std::abs(glm::degrees(angle)));
  }
  if (angles.empty()) return 180;
  std::nth_element(angles.begin(), angles.begin() + angles.size() / 2, angles.end());
  return angles[angles.size() / 2];
}

SurfaceMap with_map_turned(SurfaceMap map, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  map.uv_min = glm::dvec2(1e300), map.uv_max = glm::dvec2(-1e300);
  for (glm::dvec2& q : map.uv) {
    q = glm::dvec2(c * q.x - s * q.y, s * q.x + c * q.y);
    map.uv_min = glm::min(map.uv_min, q), map.uv_max = glm::max(map.uv_max, q);
  }
  return map;
}

// A sheet whose map was turned a quarter turn is shown the way the camera shows the sheet: each
// edge points the same way in both views, from any side; without the turn they are 90 degrees off.
TEST(Renderer, TheMapIsTurnedAsTheCameraShowsTheSurface) {
  const SurfaceMap map = with_map_turned(test::flat_unit_square(), glm::radians(90.0));
  const double aspect = 1.6;
  for (const float yaw : {-1.3f, 0.0f, 2.0f, -2.8f}) {
    render::OrbitCamera camera = render::frame_surface(map.mesh, aspect);
    camera.yaw = yaw, camera.pitch = 1.35f;  // nearly from above: the sheet is barely foreshortened
    SCOPED_TRACE(yaw);
    const double turn = render::map_turn_to_match(map, camera, aspect);
    EXPECT_LT(median_edge_angle_deg(map, camera, render::frame_map(map, aspect, 0, 0, turn), aspect), 3.0);
    const double unturned = median_edge_angle_deg(map, camera, render::frame_map(map, aspect), aspect);
    EXPECT_GT(unturned, 10.0) << "the case does not need a turn";
  }
  // The bundled pendant from its framing camera, as the studio and preview.png first show it.
  const SurfaceMap& pendant = *test::bundled_map("pendant");
  const render::OrbitCamera camera = render::frame_surface(pendant.mesh, aspect);
  const double turn = render::map_turn_to_match(pendant, camera, aspect);
  EXPECT_LT(median_edge_angle_deg(pendant, camera, render::frame_map(pendant, aspect, 0, 0, turn), aspect), 20.0);
}

// The projection the renderer draws with and the screen offsets the studio's overlays use agree,
// and the turned frame holds the whole map with its margin, beside the inset.
TEST(Renderer, ATurnedMapIsFramedWholeAndDrawnWhereTheOverlaysAre) {
  const SurfaceMap& map = dome_map();
  const double aspect = 1.6, share = 0.32;
  for (const double turn : {0.0, 0.7, -2.0, 3.0}) {
    SCOPED_TRACE(turn);
    const render::MapView v = render::frame_map(map, aspect, share, 0, turn);
    const glm::mat4 projection = v.projection(float(aspect));
    double widest = 0, tallest = 0;
    for (const glm::dvec2& q : map.uv) {
      const glm::dvec2 offset = v.screen_offset(q);
      const glm::vec4 clip = projection * glm::vec4(glm::vec2(q), 0, 1);
      EXPECT_NEAR(clip.x, offset.x / (v.half_height * aspect), 1e-4);
      EXPECT_NEAR(clip.y, offset.y / v.half_height, 1e-4);
      EXPECT_NEAR(glm::length(v.map_point(offset) - q), 0, 1e-5);
      // Inside the view, left of the inset's share.
      EXPECT_GE(clip.x, -1.0f);
      EXPECT_LE(clip.x, 1.0f - 2 * float(share));
      EXPECT_LE(std::abs(clip.y), 1.0f);
      widest = std::max(widest, double(clip.x)), tallest = std::max(tallest, std::abs(double(clip.y)));
    }
    EXPECT_GT(std::max(widest / (1 - 2 * share), tallest), 0.8) << "framed loosely";
  }
}

// A band's seamless map only ever turns by a half turn: its length stays across the view.
TEST(Renderer, ABandsMapTurnsByHalfTurnsOnly) {
  const std::shared_ptr<const SurfaceMap> ring = test::bundled_map("ring_band");
  ASSERT_TRUE(ring->seamless) << ring->seamless_unavailable;
  const SurfaceMap& band = *ring->seamless;
  for (const float yaw : {0.0f, 1.0f, 2.5f, -2.0f}) {
    render::OrbitCamera camera = render::frame_surface(band.mesh, 1.6);
    camera.yaw = yaw;
    const double turn = render::map_turn_to_match(band, camera, 1.6);
    EXPECT_TRUE(turn == 0 || std::abs(turn - glm::pi<double>()) < 1e-12) << yaw << ": " << turn;
    // And the half turn that shows it the better way round.
    const double other = turn == 0 ? glm::pi<double>() : 0;
    EXPECT_LE(median_edge_angle_deg(band, camera, render::frame_map(band, 1.6, 0, 0, turn), 1.6),
              median_edge_angle_deg(band, camera, render::frame_map(band, 1.6, 0, 0, other), 1.6))
        << yaw;
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
