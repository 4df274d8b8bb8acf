#include "paver/compute/gpu_buffer.h"

#include <algorithm>
#include <cstring>

namespace paver::gpu {

GpuBuffer::GpuBuffer(VulkanContext::Impl& ctx, vk::DeviceSize bytes, vk::BufferUsageFlags usage,
                     vk::MemoryPropertyFlags required, vk::MemoryPropertyFlags preferred)
    : size_(bytes) {
  // Zero-sized buffers are not allowed; empty arrays still need a binding.
  const vk::DeviceSize allocated = std::max<vk::DeviceSize>(bytes, 16);
  buffer_.emplace(*ctx.device, vk::BufferCreateInfo({}, allocated, usage, vk::SharingMode::eExclusive));
  const auto needs = buffer_->getMemoryRequirements();
  memory_.emplace(*ctx.device,
                  vk::MemoryAllocateInfo(needs.size, ctx.memory_type(needs.memoryTypeBits, required, preferred)));
  buffer_->bindMemory(**memory_, 0);
}

void* GpuBuffer::mapped() {
  if (!mapped_) mapped_ = memory_->mapMemory(0, VK_WHOLE_SIZE);
  return mapped_;
}

std::size_t StagingArena::take(std::size_t bytes) {
  const std::size_t offset = (used_ + 15) & ~std::size_t(15);
  const std::size_t needed = offset + bytes;
  if (!buffer_.valid() || needed > buffer_.size()) {
    const std::size_t capacity = std::max({needed, std::size_t(2 * buffer_.size()), std::size_t(1) << 16});
    GpuBuffer larger(*ctx_, capacity, usage_,
                     vk::MemoryPropertyFlagBits::eHostVisible | vk::MemoryPropertyFlagBits::eHostCoherent,
                     vk::MemoryPropertyFlagBits::eHostCached);
    if (used_ > 0) std::memcpy(larger.mapped(), buffer_.mapped(), used_);
    buffer_ = std::move(larger);
  }
  used_ = needed;
  return offset;
}

void Transfers::upload(const GpuBuffer& target, const void* data, std::size_t bytes) {
  if (bytes == 0) return;
  const std::size_t offset = up_.take(bytes);
  std::memcpy(up_.at(offset), data, bytes);
  uploads_.push_back({target.handle(), offset, bytes, nullptr});
}

void Transfers::download(const GpuBuffer& source, void* out, std::size_t bytes) {
  if (bytes == 0) return;
  downloads_.push_back({source.handle(), down_.take(bytes), bytes, out});
}

void Transfers::record_uploads(vk::raii::CommandBuffer& cb) {
  if (uploads_.empty()) return;
  for (const Copy& c : uploads_) cb.copyBuffer(up_.handle(), c.device, vk::BufferCopy(c.offset, 0, c.bytes));
  const vk::MemoryBarrier barrier(vk::AccessFlagBits::eTransferWrite,
                                  vk::AccessFlagBits::eShaderRead | vk::AccessFlagBits::eShaderWrite);
  cb.pipelineBarrier(vk::PipelineStageFlagBits::eTransfer, vk::PipelineStageFlagBits::eComputeShader, {}, barrier, {}, {});
}

void Transfers::record_downloads(vk::raii::CommandBuffer& cb) {
  if (downloads_.empty()) return;
  const vk::MemoryBarrier before(vk::AccessFlagBits::eShaderWrite, vk::AccessFlagBits::eTransferRead);
  cb.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader, vk::PipelineStageFlagBits::eTransfer, {}, before, {}, {});
  for (const Copy& c : downloads_) cb.copyBuffer(c.device, down_.handle(), vk::BufferCopy(0, c.offset, c.bytes));
  const vk::MemoryBarrier after(vk::AccessFlagBits::eTransferWrite, vk::AccessFlagBits::eHostRead);
  cb.pipelineBarrier(vk::PipelineStageFlagBits::eTransfer, vk::PipelineStageFlagBits::eHost, {}, after, {}, {});
}

void Transfers::finish() {
  for (const Copy& c : downloads_) std::memcpy(c.out, down_.at(c.offset), c.bytes);
  uploads_.clear();
  downloads_.clear();
  up_.clear();
  down_.clear();
}

}  // namespace paver::gpu
