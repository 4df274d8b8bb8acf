#pragma once
// A buffer with its memory allocation, RAII-owned (compute/ and the renderer).
// Uploads and downloads go through host-visible staging buffers.
#include "paver/compute/vulkan_objects.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace paver::gpu {

class GpuBuffer {
public:
  GpuBuffer() = default;
  // Device-local when the device has such memory (lavapipe's memory is all host memory).
  GpuBuffer(VulkanContext::Impl& ctx, vk::DeviceSize bytes, vk::BufferUsageFlags usage,
            vk::MemoryPropertyFlags required = {}, vk::MemoryPropertyFlags preferred = vk::MemoryPropertyFlagBits::eDeviceLocal);

  vk::Buffer handle() const { return **buffer_; }
  vk::DeviceSize size() const { return size_; }
  bool valid() const { return buffer_.has_value(); }
  // Mapped pointer of a host-visible buffer (maps on first use).
  void* mapped();

private:
  std::optional<vk::raii::Buffer> buffer_;
  std::optional<vk::raii::DeviceMemory> memory_;
  vk::DeviceSize size_ = 0;
  void* mapped_ = nullptr;
};

// Collects staging copies into one command buffer: uploads before, downloads after the work.
class Transfers {
public:
  explicit Transfers(VulkanContext::Impl& ctx) : ctx_(ctx) {}
  void upload(const GpuBuffer& target, const void* data, std::size_t bytes);
  // Records a copy into a host buffer; `out` is filled by finish() after the wait.
  void download(const GpuBuffer& source, void* out, std::size_t bytes);
  void record_uploads(vk::raii::CommandBuffer& cb);
  void record_downloads(vk::raii::CommandBuffer& cb);
  void finish();  // copies downloaded bytes out; call after the submission completed

private:
  VulkanContext::Impl& ctx_;
  struct Copy {
    GpuBuffer staging;
    vk::Buffer device;
    std::size_t bytes;
    void* out;
  };
  std::vector<Copy> uploads_, downloads_;
};

}  // namespace paver::gpu
