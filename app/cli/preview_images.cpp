#include "preview_images.h"

#include "core/input_error.h"

#ifdef PAVER_WITH_VULKAN
#include "renderer.h"
#endif

namespace paver::cli {

#ifdef PAVER_WITH_VULKAN
namespace {
constexpr std::array<std::uint8_t, 3> kFewer{40, 110, 240}, kMore{230, 50, 210};

// `colours` with the V-elements of each defect's particles in kFewer or kMore.
std::vector<std::array<std::uint8_t, 3>> defect_marked_colours(const Pavement& pavement,
                                                               std::vector<std::array<std::uint8_t, 3>> colours) {
  std::vector<int> mark(pavement.pattern.point_count(), 0);
  for (const Pattern::Defect& d : pavement.pattern.defects)
    for (int p : d.points) mark[p] = d.valence < 6 ? -1 : 1;
  const Elements& e = pavement.elements;
  for (size_t i = 0; i < e.size(); ++i)
    if (e.kind[i] == ElementKind::Vertex && e.source[i] >= 0 && e.source[i] < int(mark.size()) && mark[e.source[i]])
      colours[i] = mark[e.source[i]] < 0 ? kFewer : kMore;
  return colours;
}
}  // namespace

struct PreviewImages::Impl {
  std::unique_ptr<render::Renderer> renderer;
};

PreviewImages PreviewImages::open() {
  gpu::ContextOptions options;
  options.graphics = true;
  auto context = gpu::VulkanContext::create(options);
  if (!context)
    throw InputError("--png needs a Vulkan device to render with: " + context.error().message +
                     "; install a Vulkan driver (Mesa's lavapipe: mesa-vulkan-drivers), check VK_ICD_FILENAMES, or "
                     "leave out --png");
  auto renderer = render::Renderer::create(context.value());
  if (!renderer) throw InputError("--png: " + renderer.error().message);
  return PreviewImages(std::make_unique<Impl>(Impl{std::move(renderer.value())}));
}

void PreviewImages::write(const std::filesystem::path& folder, const SurfaceMap& map, const Pavement& pavement,
                          const ShapeMesh* custom, PreviewSize size) {
  render::Renderer& r = *impl_->renderer;
  const SurfaceMap& points_map = pavement_map(map, pavement);  // a band's seamless map, when paved on it
  r.set_surface(points_map);
  const auto stone_colours =
      render::element_colours(pavement.elements, render::ColourMode::NeighbourRatio, pavement.design.elements.gap);
  auto colours = stone_colours;
  Elements with_beads;  // the beads are drawn with the stones, as they are exported
  const Elements& drawn = stones_and_beads(pavement, with_beads, &colours);
  r.set_elements(drawn, colours, custom);
  r.set_pattern(points_map, pavement.pattern, pavement.points);
  render::SceneStyle style;
  const double aspect = double(size.width) / double(size.height);
  const render::OrbitCamera camera = render::frame_surface(map.mesh);
  r.render_3d(size.width, size.height, camera, style);
  render::Image preview = r.read_back(0);
  render::draw_ratio_legend(preview);
  render::write_png(folder / "preview.png", preview);
  style.show_lattice = true;
  // The map view marks an adaptive pattern's point defects on the V-elements around them.
  const bool marks_defects = !pavement.pattern.defects.empty();
  if (marks_defects)
    r.set_elements(pavement.elements, defect_marked_colours(pavement, stone_colours), custom);
  // The map beside the legends, not under them, turned as preview.png shows the surface.
  const double legend_share = double(render::legend_column_width(size.height)) / double(size.width);
  r.render_2d(size.width, size.height,
              render::frame_map(points_map, aspect, 0, legend_share, render::map_turn_to_match(points_map, camera, aspect)),
              style);
  render::Image param = r.read_back(1);
  render::draw_ratio_legend(param);  // the stones are coloured by their ratio here too
  if (marks_defects) render::draw_defect_legend(param, kFewer, kMore);
  render::write_png(folder / "param.png", param);
}
void PreviewImages::write_solid(const std::filesystem::path& path, const SurfaceMesh& solid, const SurfaceMesh& surface,
                                PreviewSize size) {
  render::Renderer& r = *impl_->renderer;
  // The renderer draws a map's surface: the solid with area-weighted vertex normals (its seats'
  // edges shade softly, which reads better at this size than flat facets) and no map.
  SurfaceMap view;
  view.mesh = solid;
  view.uv.assign(solid.positions.size(), glm::dvec2(0));
  view.normals.assign(solid.positions.size(), glm::dvec3(0));
  for (const glm::ivec3& t : solid.triangles) {
    const glm::dvec3 n = glm::cross(solid.positions[std::size_t(t.y)] - solid.positions[std::size_t(t.x)],
                                    solid.positions[std::size_t(t.z)] - solid.positions[std::size_t(t.x)]);
    for (const int c : {t.x, t.y, t.z}) view.normals[std::size_t(c)] += n;
  }
  for (glm::dvec3& n : view.normals) n = glm::length(n) > 0 ? glm::normalize(n) : glm::dvec3(0, 0, 1);
  r.set_surface(view);
  r.set_elements(Elements{}, {}, nullptr);
  render::SceneStyle style;
  style.show_elements = false;
  r.render_3d(size.width, size.height, render::frame_surface(surface), style);
  render::write_png(path, r.read_back(0));
}
#else
struct PreviewImages::Impl {};

PreviewImages PreviewImages::open() { throw InputError("--png: this paver was built without Vulkan"); }

void PreviewImages::write(const std::filesystem::path&, const SurfaceMap&, const Pavement&, const ShapeMesh*,
                          PreviewSize) {}
void PreviewImages::write_solid(const std::filesystem::path&, const SurfaceMesh&, const SurfaceMesh&, PreviewSize) {}
#endif

PreviewImages::PreviewImages(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
PreviewImages::~PreviewImages() = default;
PreviewImages::PreviewImages(PreviewImages&&) noexcept = default;
PreviewImages& PreviewImages::operator=(PreviewImages&&) noexcept = default;

}  // namespace paver::cli
