#include "paver/compute/gpu_buffer.h"

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

namespace {

GpuBuffer staging_buffer(VulkanContext::Impl& ctx, std::size_t bytes, vk::BufferUsageFlags usage) {
  return GpuBuffer(ctx, bytes, usage,
                   vk::MemoryPropertyFlagBits::eHostVisible | vk::MemoryPropertyFlagBits::eHostCoherent,
                   vk::MemoryPropertyFlagBits::eHostCached);
}

}  // namespace

void Transfers::upload(const GpuBuffer& target, const void* data, std::size_t bytes) {
  if (bytes == 0) return;
  GpuBuffer staging = staging_buffer(ctx_, bytes, vk::BufferUsageFlagBits::eTransferSrc);
  std::memcpy(staging.mapped(), data, bytes);
  uploads_.push_back({std::move(staging), target.handle(), bytes, nullptr});
}

void Transfers::download(const GpuBuffer& source, void* out, std::size_t bytes) {
  if (bytes == 0) return;
  downloads_.push_back({staging_buffer(ctx_, bytes, vk::BufferUsageFlagBits::eTransferDst), source.handle(), bytes, out});
}

void Transfers::record_uploads(vk::raii::CommandBuffer& cb) {
  if (uploads_.empty()) return;
  for (const Copy& c : uploads_) cb.copyBuffer(c.staging.handle(), c.device, vk::BufferCopy(0, 0, c.bytes));
  const vk::MemoryBarrier barrier(vk::AccessFlagBits::eTransferWrite,
                                  vk::AccessFlagBits::eShaderRead | vk::AccessFlagBits::eShaderWrite);
  cb.pipelineBarrier(vk::PipelineStageFlagBits::eTransfer, vk::PipelineStageFlagBits::eComputeShader, {}, barrier, {}, {});
}

void Transfers::record_downloads(vk::raii::CommandBuffer& cb) {
  if (downloads_.empty()) return;
  const vk::MemoryBarrier before(vk::AccessFlagBits::eShaderWrite, vk::AccessFlagBits::eTransferRead);
  cb.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader, vk::PipelineStageFlagBits::eTransfer, {}, before, {}, {});
  for (const Copy& c : downloads_) cb.copyBuffer(c.device, c.staging.handle(), vk::BufferCopy(0, 0, c.bytes));
  const vk::MemoryBarrier after(vk::AccessFlagBits::eTransferWrite, vk::AccessFlagBits::eHostRead);
  cb.pipelineBarrier(vk::PipelineStageFlagBits::eTransfer, vk::PipelineStageFlagBits::eHost, {}, after, {}, {});
}

void Transfers::finish() {
  for (Copy& c : downloads_) std::memcpy(c.out, c.staging.mapped(), c.bytes);
  uploads_.clear();
  downloads_.clear();
}

}  // namespace paver::gpu
