#include "preview_images.h"

#include "core/input_error.h"

#ifdef PAVER_WITH_VULKAN
#include "renderer.h"
#endif

namespace paver::cli {

#ifdef PAVER_WITH_VULKAN
struct PreviewImages::Impl {
  std::unique_ptr<render::Renderer> renderer;
};

PreviewImages PreviewImages::open() {
  gpu::ContextOptions options;
  options.graphics = true;
  auto context = gpu::VulkanContext::create(options);
  if (!context) throw InputError("--png needs a Vulkan device to render with: " + context.error().message);
  auto renderer = render::Renderer::create(context.value());
  if (!renderer) throw InputError("--png: " + renderer.error().message);
  return PreviewImages(std::make_unique<Impl>(Impl{std::move(renderer.value())}));
}

void PreviewImages::write(const std::filesystem::path& folder, const SurfaceMap& map, const Pavement& pavement,
                          const ShapeMesh* custom, PreviewSize size) {
  render::Renderer& r = *impl_->renderer;
  r.set_surface(map);
  r.set_elements(pavement.elements, render::element_colours(pavement.elements, render::ColourMode::NeighbourRatio, pavement.design.elements.gap),
                 custom);
  r.set_pattern(map, pavement.pattern, pavement.points);
  render::SceneStyle style;
  r.render_3d(size.width, size.height, render::frame_surface(map.mesh), style);
  render::Image preview = r.read_back(0);
  render::draw_ratio_legend(preview);
  render::write_png(folder / "preview.png", preview);
  style.show_lattice = true;
  r.render_2d(size.width, size.height, render::frame_map(map), style);
  render::write_png(folder / "param.png", r.read_back(1));
}
#else
struct PreviewImages::Impl {};

PreviewImages PreviewImages::open() { throw InputError("--png: this paver was built without Vulkan"); }

void PreviewImages::write(const std::filesystem::path&, const SurfaceMap&, const Pavement&, const ShapeMesh*,
                          PreviewSize) {}
#endif

PreviewImages::PreviewImages(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
PreviewImages::~PreviewImages() = default;
PreviewImages::PreviewImages(PreviewImages&&) noexcept = default;
PreviewImages& PreviewImages::operator=(PreviewImages&&) noexcept = default;

}  // namespace paver::cli
