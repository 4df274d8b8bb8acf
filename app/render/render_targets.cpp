#include "render_targets.h"

namespace paver::render {
namespace {

ImageWithMemory make_image(gpu::VulkanContext::Impl& vk, int w, int h, vk::Format format, vk::ImageUsageFlags usage,
                           vk::ImageAspectFlags aspect) {
  ImageWithMemory out;
  out.image.emplace(*vk.device,
                    vk::ImageCreateInfo({}, vk::ImageType::e2D, format, vk::Extent3D(std::uint32_t(w), std::uint32_t(h), 1),
                                        1, 1, vk::SampleCountFlagBits::e1, vk::ImageTiling::eOptimal, usage));
  const auto needs = out.image->getMemoryRequirements();
  out.memory.emplace(*vk.device, vk::MemoryAllocateInfo(needs.size, vk.memory_type(needs.memoryTypeBits, {},
                                                                                    vk::MemoryPropertyFlagBits::eDeviceLocal)));
  out.image->bindMemory(**out.memory, 0);
  out.view.emplace(*vk.device, vk::ImageViewCreateInfo({}, **out.image, vk::ImageViewType::e2D, format, {},
                                                       vk::ImageSubresourceRange(aspect, 0, 1, 0, 1)));
  return out;
}

}  // namespace

bool RenderTarget::ensure(gpu::VulkanContext::Impl& vk, const vk::raii::RenderPass& pass, int w, int h) {
  w = std::max(w, 1), h = std::max(h, 1);
  if (framebuffer && w == width && h == height) return false;
  vk.device->waitIdle();  // the old images may still be in use by a frame in flight
  framebuffer.reset();
  colour = make_image(vk, w, h, kColourFormat,
                      vk::ImageUsageFlagBits::eColorAttachment | vk::ImageUsageFlagBits::eSampled |
                          vk::ImageUsageFlagBits::eTransferSrc,
                      vk::ImageAspectFlagBits::eColor);
  depth = make_image(vk, w, h, kDepthFormat, vk::ImageUsageFlagBits::eDepthStencilAttachment,
                     vk::ImageAspectFlagBits::eDepth);
  const vk::ImageView attachments[] = {**colour.view, **depth.view};
  framebuffer.emplace(*vk.device, vk::FramebufferCreateInfo({}, *pass, attachments, std::uint32_t(w), std::uint32_t(h), 1));
  width = w, height = h;
  ++generation;
  return true;
}

}  // namespace paver::render
