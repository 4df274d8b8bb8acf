#include "paver/compute/vulkan_objects.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <functional>
#include <sstream>

namespace paver::gpu {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

std::string type_name(vk::PhysicalDeviceType t) {
  switch (t) {
    case vk::PhysicalDeviceType::eDiscreteGpu: return "discrete";
    case vk::PhysicalDeviceType::eIntegratedGpu: return "integrated";
    case vk::PhysicalDeviceType::eVirtualGpu: return "virtual";
    case vk::PhysicalDeviceType::eCpu: return "cpu";
    default: return "other";
  }
}

// Lower is better: the order the issue asks for.
int preference(vk::PhysicalDeviceType t) {
  switch (t) {
    case vk::PhysicalDeviceType::eDiscreteGpu: return 0;
    case vk::PhysicalDeviceType::eIntegratedGpu: return 1;
    case vk::PhysicalDeviceType::eVirtualGpu: return 2;
    case vk::PhysicalDeviceType::eCpu: return 3;
    default: return 4;
  }
}

std::string version_text(std::uint32_t v) {
  std::ostringstream s;
  s << VK_API_VERSION_MAJOR(v) << "." << VK_API_VERSION_MINOR(v) << "." << VK_API_VERSION_PATCH(v);
  return s.str();
}

// A queue family with compute (and graphics, and presentation, when asked for).
std::optional<std::uint32_t> queue_family(const vk::raii::Instance* instance, const vk::raii::PhysicalDevice& device,
                                          const ContextOptions& options) {
  const auto families = device.getQueueFamilyProperties();
  for (std::uint32_t i = 0; i < families.size(); ++i) {
    if (!(families[i].queueFlags & vk::QueueFlagBits::eCompute)) continue;
    if (options.graphics && !(families[i].queueFlags & vk::QueueFlagBits::eGraphics)) continue;
    if (options.can_present && instance &&
        !options.can_present(static_cast<VkInstance>(**instance), static_cast<VkPhysicalDevice>(*device), i))
      continue;
    return i;
  }
  return std::nullopt;
}

std::optional<std::uint32_t> compute_queue_family(const vk::raii::PhysicalDevice& device) {
  return queue_family(nullptr, device, ContextOptions{});
}

// The solver's move pass reduces with subgroupMax: the device must offer subgroup arithmetic in
// compute shaders.
bool has_subgroup_arithmetic(const vk::raii::PhysicalDevice& device) {
  const auto chain = device.getProperties2<vk::PhysicalDeviceProperties2, vk::PhysicalDeviceSubgroupProperties>();
  const auto& sub = chain.get<vk::PhysicalDeviceSubgroupProperties>();
  return (sub.supportedStages & vk::ShaderStageFlagBits::eCompute) &&
         (sub.supportedOperations & vk::SubgroupFeatureFlagBits::eArithmetic);
}

DeviceInfo describe(const vk::raii::PhysicalDevice& device) {
  const auto p = device.getProperties();
  DeviceInfo info;
  info.name = p.deviceName.data();
  info.type = type_name(p.deviceType);
  info.api_version = version_text(p.apiVersion);
  info.compute = compute_queue_family(device).has_value() && p.apiVersion >= VK_API_VERSION_1_2 &&
                 has_subgroup_arithmetic(device);
  return info;
}

VKAPI_ATTR VkBool32 VKAPI_CALL on_validation_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                     VkDebugUtilsMessageTypeFlagsEXT,
                                                     const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  auto* impl = static_cast<VulkanContext::Impl*>(user);
  const char* level = severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT ? "error" : "warning";
  std::lock_guard lock(impl->log_mutex);
  impl->log.push_back(std::string(level) + ": " + (data && data->pMessage ? data->pMessage : "(no text)"));
  return VK_FALSE;
}

bool has_layer(const vk::raii::Context& context, const char* name) {
  for (const auto& layer : context.enumerateInstanceLayerProperties())
    if (std::string(layer.layerName.data()) == name) return true;
  return false;
}

vk::raii::Instance make_instance(const vk::raii::Context& context, bool validation,
                                 vk::DebugUtilsMessengerCreateInfoEXT* messenger_info,
                                 const std::vector<std::string>& extra_extensions = {}) {
  vk::ApplicationInfo app("paver", 1, "paver", 1, VK_API_VERSION_1_2);
  std::vector<const char*> layers, extensions;
  for (const auto& e : extra_extensions) extensions.push_back(e.c_str());
  if (validation) {
    layers.push_back(kValidationLayer);
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  }
  vk::InstanceCreateInfo info({}, &app, layers, extensions);
  // Synchronization validation too: a missing barrier between passes is the bug to catch here.
  const vk::ValidationFeatureEnableEXT enables[] = {vk::ValidationFeatureEnableEXT::eSynchronizationValidation};
  vk::ValidationFeaturesEXT features(enables, {});
  if (validation) {
    features.pNext = messenger_info;
    info.pNext = &features;
  }
  return vk::raii::Instance(context, info);
}

}  // namespace

Error vulkan_error(const std::string& doing, const std::exception& e) {
  return Error{"Vulkan: " + doing + " failed: " + e.what()};
}

std::uint32_t VulkanContext::Impl::memory_type(std::uint32_t type_bits, vk::MemoryPropertyFlags required,
                                               vk::MemoryPropertyFlags preferred) const {
  std::optional<std::uint32_t> fallback;
  for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i) {
    if (!(type_bits & (1u << i))) continue;
    const auto flags = memory.memoryTypes[i].propertyFlags;
    if ((flags & required) != required) continue;
    if ((flags & preferred) == preferred) return i;
    if (!fallback) fallback = i;
  }
  if (!fallback) throw std::runtime_error("no suitable memory type");
  return *fallback;
}

void VulkanContext::Impl::submit_and_wait(const std::function<void(vk::raii::CommandBuffer&)>& record) {
  vk::raii::CommandBuffers buffers(*device, vk::CommandBufferAllocateInfo(**command_pool, vk::CommandBufferLevel::ePrimary, 1));
  vk::raii::CommandBuffer& cb = buffers.front();
  cb.begin(vk::CommandBufferBeginInfo(vk::CommandBufferUsageFlagBits::eOneTimeSubmit));
  record(cb);
  cb.end();
  vk::raii::Fence fence(*device, vk::FenceCreateInfo());
  const vk::CommandBuffer raw = *cb;
  queue->submit(vk::SubmitInfo({}, {}, raw), *fence);
  if (device->waitForFences(*fence, VK_TRUE, UINT64_MAX) != vk::Result::eSuccess)
    throw std::runtime_error("waiting for the GPU failed");
}

Result<std::vector<DeviceInfo>> list_devices() {
  try {
    vk::raii::Context context;
    const vk::raii::Instance instance = make_instance(context, false, nullptr);
    std::vector<DeviceInfo> out;
    for (const auto& device : vk::raii::PhysicalDevices(instance)) out.push_back(describe(device));
    return out;
  } catch (const std::exception& e) {
    return Error{std::string("no Vulkan available (") + e.what() +
                 "); install a driver, e.g. Debian's mesa-vulkan-drivers for the lavapipe CPU device"};
  }
}

VulkanContext::VulkanContext() : impl_(std::make_unique<Impl>()) {}
VulkanContext::~VulkanContext() {
  // Device work must be finished before the RAII members go, in reverse order of creation.
  if (impl_ && impl_->device) impl_->device->waitIdle();
}

Result<std::shared_ptr<VulkanContext>> VulkanContext::create(const ContextOptions& options) {
  std::shared_ptr<VulkanContext> ctx(new VulkanContext());
  Impl& d = *ctx->impl_;
  try {
    const char* env_validation = std::getenv("PAVER_VULKAN_VALIDATION");
    bool validation = options.validation || (env_validation && std::string(env_validation) == "1");
    if (validation && !has_layer(d.context, kValidationLayer))
      return Error{"Vulkan validation was asked for but VK_LAYER_KHRONOS_validation is not installed "
                   "(Debian: vulkan-validationlayers)"};
    vk::DebugUtilsMessengerCreateInfoEXT messenger_info(
        {}, vk::DebugUtilsMessageSeverityFlagBitsEXT::eWarning | vk::DebugUtilsMessageSeverityFlagBitsEXT::eError,
        vk::DebugUtilsMessageTypeFlagBitsEXT::eValidation | vk::DebugUtilsMessageTypeFlagBitsEXT::ePerformance,
        &on_validation_message, &d);
    d.instance.emplace(make_instance(d.context, validation, &messenger_info, options.instance_extensions));
    d.validation = validation;
    if (validation) d.messenger.emplace(*d.instance, messenger_info);

    vk::raii::PhysicalDevices devices(*d.instance);
    if (devices.empty()) return Error{"Vulkan found no device; install a driver (e.g. mesa-vulkan-drivers)"};
    std::string wanted = options.device;
    bool from_environment = false;
    if (wanted.empty())
      if (const char* env = std::getenv("PAVER_VULKAN_DEVICE")) wanted = env, from_environment = true;
    int best = -1, best_rank = 1 << 30;
    std::string seen;
    for (int i = 0; i < int(devices.size()); ++i) {
      const DeviceInfo info = describe(devices[i]);
      seen += (seen.empty() ? "" : ", ") + info.name + " (" + info.type + ")";
      if (!info.compute || !queue_family(&*d.instance, devices[i], options)) continue;
      if (!wanted.empty() && lower(info.name).find(lower(wanted)) == std::string::npos) continue;
      const int rank = preference(devices[i].getProperties().deviceType);
      if (rank < best_rank) best_rank = rank, best = i;
    }
    if (best < 0)
      return Error{wanted.empty() ? std::string("no Vulkan 1.2 device with a ") +
                                        (options.graphics ? "graphics and compute" : "compute") + " queue" +
                                        (options.can_present ? " that can present" : "") + " among: " + seen
                                  : "no Vulkan device matches \"" + wanted + "\"" +
                                        // The user has to know where the name came from to change it.
                                        (from_environment ? " (from $PAVER_VULKAN_DEVICE)" : "") + "; found: " + seen};
    d.physical_device.emplace(std::move(devices[best]));
    d.info = describe(*d.physical_device);
    d.queue_family = *queue_family(&*d.instance, *d.physical_device, options);
    d.memory = d.physical_device->getMemoryProperties();
    const float priority = 1.0f;
    vk::DeviceQueueCreateInfo queue_info({}, d.queue_family, 1, &priority);
    std::vector<const char*> device_extensions;
    if (options.can_present) device_extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
    d.device.emplace(*d.physical_device, vk::DeviceCreateInfo({}, queue_info, {}, device_extensions));
    d.queue.emplace(*d.device, d.queue_family, 0);
    d.command_pool.emplace(*d.device, vk::CommandPoolCreateInfo(vk::CommandPoolCreateFlagBits::eResetCommandBuffer,
                                                                d.queue_family));
  } catch (const std::exception& e) {
    return vulkan_error("creating the instance and device", e);
  }
  return ctx;
}

const DeviceInfo& VulkanContext::device() const { return impl_->info; }
bool VulkanContext::validation_enabled() const { return impl_->validation; }
int VulkanContext::validation_message_count() const {
  std::lock_guard lock(impl_->log_mutex);
  return int(impl_->log.size());
}
std::vector<std::string> VulkanContext::validation_messages() const {
  std::lock_guard lock(impl_->log_mutex);
  return impl_->log;
}

}  // namespace paver::gpu
