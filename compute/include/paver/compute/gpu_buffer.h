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

// Host-visible staging memory kept from one submission to the next, sub-allocated by offset:
// allocating a staging buffer for every copy made each solve pay the driver's allocation a few
// dozen times (on an NVIDIA H100, most of a small pavement's time on the GPU).
class StagingArena {
public:
  StagingArena(VulkanContext::Impl& ctx, vk::BufferUsageFlags usage) : ctx_(&ctx), usage_(usage) {}
  // Room for `bytes` more; returns its offset. Growing moves the contents to a larger buffer, so
  // handle() is read when the copies are recorded, after every take().
  std::size_t take(std::size_t bytes);
  void* at(std::size_t offset) { return static_cast<char*>(buffer_.mapped()) + offset; }
  vk::Buffer handle() const { return buffer_.handle(); }
  void clear() { used_ = 0; }

private:
  VulkanContext::Impl* ctx_;
  vk::BufferUsageFlags usage_;
  GpuBuffer buffer_;
  std::size_t used_ = 0;
};

// Collects staging copies into one command buffer: uploads before, downloads after the work.
class Transfers {
public:
  Transfers(StagingArena& uploads, StagingArena& downloads) : up_(uploads), down_(downloads) {}
  // A solve that threw between two submissions leaves the arenas free for the next one.
  ~Transfers() {
    up_.clear();
    down_.clear();
  }
  Transfers(const Transfers&) = delete;
  Transfers& operator=(const Transfers&) = delete;
  void upload(const GpuBuffer& target, const void* data, std::size_t bytes);
  // Records a copy into a host buffer; `out` is filled by finish() after the wait.
  void download(const GpuBuffer& source, void* out, std::size_t bytes);
  void record_uploads(vk::raii::CommandBuffer& cb);
  void record_downloads(vk::raii::CommandBuffer& cb);
  void finish();  // copies downloaded bytes out; call after the submission completed

private:
  StagingArena& up_;
  StagingArena& down_;
  struct Copy {
    vk::Buffer device;
    std::size_t offset;  // in the arena
    std::size_t bytes;
    void* out;
  };
  std::vector<Copy> uploads_, downloads_;
};

}  // namespace paver::gpu
