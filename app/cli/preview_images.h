#pragma once
// `paver run --png`: preview.png (the 3D view, framed on the surface, with the colour legend)
// and param.png (the 2D parameter view), rendered offscreen by the shared Vulkan renderer.
#include "pipeline/pavement.h"
#include "map/surface_map.h"

#include <filesystem>

namespace paver::cli {

struct PreviewSize {
  int width = 1280, height = 800;
};

// Throws InputError when there is no Vulkan device to render with.
void write_preview_images(const std::filesystem::path& folder, const SurfaceMap& map, const Pavement& pavement,
                          const ShapeMesh* custom, PreviewSize size = {});

}  // namespace paver::cli
