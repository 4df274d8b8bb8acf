#pragma once
// `paver run --png`: preview.png (the 3D view, framed on the surface, with the colour legend)
// and param.png (the 2D parameter view), and with --subtract cut.png (the metal with its seats),
// rendered offscreen by the shared Vulkan renderer.
#include "map/surface_map.h"
#include "pipeline/pavement.h"

#include <filesystem>
#include <memory>

namespace paver::cli {

struct PreviewSize {
  int width = 1280, height = 800;
};

class PreviewImages {
public:
  // Opens a Vulkan device and the renderer; throws InputError ("--png ...") when there is none,
  // so that `paver run --png` fails before any work, not after it.
  static PreviewImages open();
  ~PreviewImages();
  PreviewImages(PreviewImages&&) noexcept;
  PreviewImages& operator=(PreviewImages&&) noexcept;

  void write(const std::filesystem::path& folder, const SurfaceMap& map, const Pavement& pavement,
             const ShapeMesh* custom, PreviewSize size = {});

  // cut.png: the metal with its seats (`solid`, closed), seen as preview.png sees the surface
  // (`surface` frames the camera), without the stones so that the seats show.
  void write_solid(const std::filesystem::path& path, const SurfaceMesh& solid, const SurfaceMesh& surface,
                   PreviewSize size = {});

private:
  struct Impl;
  explicit PreviewImages(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace paver::cli
