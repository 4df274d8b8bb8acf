#pragma once
// The renderer's offscreen images: a colour image (sampled by the studio, copied for PNGs) and a
// depth image, with their framebuffer; re-created when the requested size changes.
#include "paver/compute/vulkan_objects.h"

#include <optional>

namespace paver::render {

constexpr vk::Format kColourFormat = vk::Format::eR8G8B8A8Unorm;
constexpr vk::Format kDepthFormat = vk::Format::eD32Sfloat;

struct ImageWithMemory {
  std::optional<vk::raii::Image> image;
  std::optional<vk::raii::DeviceMemory> memory;
  std::optional<vk::raii::ImageView> view;
};

struct RenderTarget {
  int width = 0, height = 0;
  int generation = 0;
  ImageWithMemory colour, depth;
  std::optional<vk::raii::Framebuffer> framebuffer;

  // (Re)creates the images when the size differs; returns true when it did.
  bool ensure(gpu::VulkanContext::Impl& vk, const vk::raii::RenderPass& pass, int w, int h);
};

}  // namespace paver::render
