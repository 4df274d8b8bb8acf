#pragma once
// The Vulkan objects behind VulkanContext, for compute/ and the renderer in app/: RAII-owned by
// Vulkan-Hpp, so a failure anywhere unwinds cleanly and nothing leaks a handle. Includes
// vulkan_raii.hpp (slow to compile): include it only where Vulkan calls are made.
#include "paver/compute/vulkan_context.h"

#include <vulkan/vulkan_raii.hpp>

#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace paver::gpu {

struct VulkanContext::Impl {
  vk::raii::Context context;
  std::optional<vk::raii::Instance> instance;
  std::optional<vk::raii::DebugUtilsMessengerEXT> messenger;
  std::optional<vk::raii::PhysicalDevice> physical_device;
  std::optional<vk::raii::Device> device;
  std::optional<vk::raii::Queue> queue;
  std::optional<vk::raii::CommandPool> command_pool;
  std::uint32_t queue_family = 0;
  DeviceInfo info;
  bool validation = false;
  vk::PhysicalDeviceMemoryProperties memory;

  mutable std::mutex log_mutex;
  std::vector<std::string> log;  // validation messages

  // Memory type with all `required` flags among `type_bits`, preferring `preferred` too.
  std::uint32_t memory_type(std::uint32_t type_bits, vk::MemoryPropertyFlags required,
                            vk::MemoryPropertyFlags preferred = {}) const;
  // Records with `record` into a fresh command buffer, submits and waits.
  void submit_and_wait(const std::function<void(vk::raii::CommandBuffer&)>& record);
};

// Turns a Vulkan-Hpp exception into an Error naming what we were doing.
Error vulkan_error(const std::string& doing, const std::exception& e);

}  // namespace paver::gpu
