#pragma once
// The one Vulkan renderer shared by the CLI (offscreen PNG previews) and Paver Studio (its 3D
// and 2D views, shown as ImGui images). It draws into its own offscreen colour + depth images;
// callers read them back (CLI) or sample them (studio).
//
// 3D view: the shaded surface and every element instanced by shape (sphere, gem, hex prism,
// disc, custom mesh), oriented by its normal and coloured per element; optionally the pattern's
// edges lifted onto the surface. 2D view: the map M^ (triangles and wireframe), the pattern's
// edges, and the elements as disks.
#include "paver/compute/result.h"
#include "paver/compute/vulkan_context.h"
#include "elements/element_shape.h"
#include "elements/elements.h"
#include "pattern/pattern.h"
#include "map/surface_map.h"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string_view>
#include <vector>

namespace paver::render {

struct PreparedElements;
struct PreparedPattern;

// Orbit camera around `target`; yaw/pitch in radians, vertical field of view in degrees.
struct OrbitCamera {
  glm::vec3 target{0};
  float distance = 1;
  float yaw = 0.6f, pitch = 0.5f;
  float fov_deg = 35;
  // The target drawn this far right of the image's centre, in clip units (-1 to 1 across): the
  // studio moves the model left of its inset so; orbiting still turns about the target.
  float screen_shift_x = 0;
  glm::mat4 view_projection(float aspect) const;
  glm::vec3 eye() const;
};
// A camera that frames the whole surface from above its mean normal, a little to the side, in an
// image `aspect` (width / height) wide whose right `right_share` of the width is kept free.
OrbitCamera frame_surface(const SurfaceMesh& mesh, double aspect = 1.6, double right_share = 0);

// 2D view: the map point at the image centre, the half height of the visible region, and how far
// the map is turned on screen (radians, counter-clockwise): a screen offset from the centre is
// R(turn) (q - centre), so that the map can be shown the way the 3D view shows the surface.
struct MapView {
  glm::vec2 centre{0};
  float half_height = 1;
  float turn = 0;
  glm::mat4 projection(float aspect) const;
  // A map point's offset from the centre as the screen shows it (map units, y up), and back.
  glm::dvec2 screen_offset(glm::dvec2 q) const;
  glm::dvec2 map_point(glm::dvec2 screen_offset) const;
};
// The whole map with a margin, turned by `turn`, in a view `aspect` (width / height) wide, leaving
// the right `right_share` of the width free (where the studio's inset sits) and the left
// `left_share` (where a PNG's legends sit).
MapView frame_map(const SurfaceMap& map, double aspect = 1.6, double right_share = 0, double left_share = 0,
                  double turn = 0);
// The turn that shows the map as `camera` shows the surface in an image `aspect` wide: the
// rotation that best takes the map's edges onto their images on screen, over the triangles that
// face the camera. A band's seamless map turns by 0 or a half turn only (its length stays across
// the view) and a closed surface's atlas (charts side by side) not at all.
double map_turn_to_match(const SurfaceMap& map, const OrbitCamera& camera, double aspect);

enum class ColourMode { NeighbourRatio, ElementType };

struct SceneStyle {
  bool show_surface = true;
  bool show_elements = true;
  bool show_lattice = false;   // pattern edges (3D: lifted; 2D: always drawn when set)
  bool show_map_wireframe = true;  // 2D only
  std::array<float, 3> background{0.13f, 0.14f, 0.16f};
};

// What the legends say, written once for the studio's screen and every PNG (CLI and studio): the
// title, the span of the ratio bar (linear in the ratio), its labelled ticks, the colour at a ratio
// (the elements' own colour), and the element-type entries. Each side draws them its own way.
inline constexpr const char* kRatioLegendTitle = "NN distance / (diameter + gap)";
inline constexpr double kRatioLegendMin = 0.9, kRatioLegendMax = 1.3;
std::vector<double> ratio_legend_ticks();
// Whether the PNG legends' bitmap font has every character of `text` (a missing one draws blank).
bool legend_can_write(std::string_view text);
// Pixels from a PNG's left edge that its legends (bottom left) take, for an image this tall.
int legend_column_width(int image_height);
std::array<std::uint8_t, 3> ratio_legend_colour(double ratio);
// Where `ratio` sits along the bar, 0 (left) to 1 (right).
double ratio_legend_position(double ratio);
struct TypeLegendEntry {
  const char* label;
  std::array<std::uint8_t, 3> rgb;
};
std::vector<TypeLegendEntry> element_type_legend();

// Per element colours for a mode: nearest-neighbour ratio scale, or V blue / E orange.
std::vector<std::array<std::uint8_t, 3>> element_colours(const Elements& elements, ColourMode mode, double gap = 0);

// How many elements the 3D view draws in each shape detail (ShapeDetail): Full up to
// kCoarseShapesAbove, Coarse up to kMinimalShapesAbove, Minimal beyond.
inline constexpr std::size_t kCoarseShapesAbove = 2000, kMinimalShapesAbove = 8000;
ShapeDetail shape_detail_for(std::size_t element_count);

// What a view is drawn with: its size, and the camera (3D) or the map view (2D) with the style.
struct ViewRequest {
  int width = 1, height = 1;
  OrbitCamera camera;  // view 0
  MapView map_view;    // view 1
  SceneStyle style;
};

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // row-major, top row first
};

class Renderer {
public:
  // Needs a context created with ContextOptions::graphics = true.
  static gpu::Result<std::unique_ptr<Renderer>> create(std::shared_ptr<gpu::VulkanContext> context);
  ~Renderer();

  // Scene content. Each call uploads what it is given; the rest stays.
  void set_surface(const SurfaceMap& map);
  void set_elements(const Elements& elements, const std::vector<std::array<std::uint8_t, 3>>& colours,
                    const ShapeMesh* custom = nullptr);
  void set_pattern(const SurfaceMap& map, const Pattern& pattern, const std::vector<glm::dvec2>& points);
  // The same, prepared beforehand (scene_data.h): a copy into the buffers.
  void set_elements(const PreparedElements& prepared);
  void set_pattern(const PreparedPattern& prepared);

  // Renders a view into the renderer's image of that view (0: 3D, 1: 2D), resized as needed.
  void render(int view, const ViewRequest& request);
  void render_3d(int width, int height, const OrbitCamera& camera, const SceneStyle& style);
  void render_2d(int width, int height, const MapView& view, const SceneStyle& style);

  // The same image drawn over several calls, for a view too heavy to draw within one frame of the
  // studio (tens of thousands of elements on a software renderer while the solver runs).
  // start_drawing begins it on a second image of the view; each draw_more adds to it for about
  // `budget_ms` (one slice at least) and returns true once it is complete, when it becomes the
  // view's image. Until then the view keeps its last complete image (image_view, read_back). A
  // scene change (set_*) or a whole render of the view drops an unfinished image.
  void start_drawing(int view, const ViewRequest& request);
  // A quick image of the view while it moves: at half the size (the studio stretches it), without
  // the elements and the pattern's lines. It is shown until the next whole or complete image.
  void render_quick(int view, const ViewRequest& request);
  bool draw_more(int view, double budget_ms);
  bool drawing(int view) const;        // an unfinished image is waiting for draw_more
  bool drawing_begun(int view) const;  // ... and draw_more has drawn a slice of it
  void stop_drawing(int view);

  // Reads a view's image back (for PNGs and tests).
  Image read_back(int view);

  // For the studio: the view's image (colour, shader-read-only layout after rendering), its view
  // handle and a sampler, as raw Vulkan handles (VkImageView, VkSampler).
  void* image_view(int view) const;
  void* sampler() const;
  // Bumps whenever a view's image was re-created (its handles changed).
  int image_generation(int view) const;

  struct Impl;

private:
  Renderer();
  std::unique_ptr<Impl> impl_;
};

// PNG through stb_image_write, written atomically. Throws InputError naming the path.
void write_png(const std::filesystem::path& path, const Image& image);

// Draws a colour legend for the nearest-neighbour ratio into the image (bottom left), with
// numbers in a small built-in bitmap font: the CLI's preview carries its own legend.
void draw_ratio_legend(Image& image);
// The element-type colours (V, E, bead), for a picture coloured by type.
void draw_type_legend(Image& image);

// The legend of the point-defect markers (param.png of an adaptive pattern): the colours of
// particles or faces with fewer than 6 neighbours or sides, and with more.
// It sits above the ratio legend, which the same picture carries.
void draw_defect_legend(Image& image, std::array<std::uint8_t, 3> fewer, std::array<std::uint8_t, 3> more);

}  // namespace paver::render
