#pragma once
// A headless Vulkan instance and compute device: no window, no surface. Device selection prefers
// a discrete GPU, then an integrated one, then a CPU implementation (Mesa lavapipe); a name
// substring (ContextOptions::device or $PAVER_VULKAN_DEVICE) overrides the preference.
#include "paver/compute/result.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace paver::gpu {

struct DeviceInfo {
  std::string name;         // e.g. "llvmpipe (LLVM 15.0.6, 256 bits)", "NVIDIA H200"
  std::string type;         // "discrete", "integrated", "virtual", "cpu" or "other"
  std::string api_version;  // e.g. "1.3.230"
  bool compute = false;     // usable: a compute queue, Vulkan 1.2, subgroup arithmetic in compute
};

struct ContextOptions {
  std::string device;       // case-insensitive substring of the device name; empty: $PAVER_VULKAN_DEVICE
  bool validation = false;  // VK_LAYER_KHRONOS_validation with synchronization validation
                            // (also on when $PAVER_VULKAN_VALIDATION=1)
  bool graphics = false;    // the queue must do graphics as well as compute (the renderer)
  // For a window: instance extensions (e.g. from glfwGetRequiredInstanceExtensions), and a test
  // that a queue family of a device can present; the device then gets VK_KHR_swapchain.
  std::vector<std::string> instance_extensions;
  std::function<bool(void* instance, void* physical_device, std::uint32_t queue_family)> can_present;
};

// Every physical device the loader finds. An Error when there is no Vulkan at all.
Result<std::vector<DeviceInfo>> list_devices();

class VulkanContext {
public:
  static Result<std::shared_ptr<VulkanContext>> create(const ContextOptions& options = {});
  ~VulkanContext();
  VulkanContext(const VulkanContext&) = delete;
  VulkanContext& operator=(const VulkanContext&) = delete;

  const DeviceInfo& device() const;
  bool validation_enabled() const;
  // Messages (warnings and errors) the validation layer sent so far, and their text.
  int validation_message_count() const;
  std::vector<std::string> validation_messages() const;

  struct Impl;  // Vulkan-Hpp RAII objects; see paver/compute/vulkan_objects.h
  Impl& impl() { return *impl_; }

private:
  VulkanContext();
  std::unique_ptr<Impl> impl_;
};

}  // namespace paver::gpu
