#include "app_window.h"
#include "studio_look.h"

#include "view_images.h"

#include "paver/compute/gpu_buffer.h"
#include "paver/compute/vulkan_objects.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>
#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

namespace paver::studio {
namespace {

// ImGui's Vulkan backend reports errors through this hook; going on with a failed call would use
// a bad handle, so it stops the frame loop with an error the studio reports.
void check_imgui_vulkan(VkResult result) {
  if (result < 0)
    throw std::runtime_error("ImGui's Vulkan backend failed with VkResult " + std::to_string(int(result)));
}

vk::SurfaceFormatKHR choose_format(const std::vector<vk::SurfaceFormatKHR>& formats) {
  // UNORM: the renderer's images are UNORM too, so sampled colours arrive unchanged.
  for (const vk::Format wanted : {vk::Format::eB8G8R8A8Unorm, vk::Format::eR8G8B8A8Unorm})
    for (const auto& f : formats)
      if (f.format == wanted && f.colorSpace == vk::ColorSpaceKHR::eSrgbNonlinear) return f;
  return formats.front();
}

vk::PresentModeKHR choose_present_mode(const std::vector<vk::PresentModeKHR>& modes, bool vsync) {
  if (!vsync)
    for (const auto wanted : {vk::PresentModeKHR::eMailbox, vk::PresentModeKHR::eImmediate})
      if (std::find(modes.begin(), modes.end(), wanted) != modes.end()) return wanted;
  return vk::PresentModeKHR::eFifo;  // always there
}

}  // namespace

struct AppWindow::Swapchain {
  gpu::VulkanContext::Impl& ctx;
  vk::raii::SurfaceKHR surface;
  vk::SurfaceFormatKHR format;
  vk::PresentModeKHR present_mode;
  std::optional<vk::raii::RenderPass> render_pass;
  std::optional<vk::raii::DescriptorPool> imgui_pool;  // the font's descriptor set
  std::optional<vk::raii::CommandBuffer> commands;
  std::optional<vk::raii::Fence> frame_done;           // the last frame's commands finished
  std::optional<vk::raii::Semaphore> image_acquired;

  std::optional<vk::raii::SwapchainKHR> swapchain;
  std::vector<vk::Image> images;
  std::vector<vk::raii::ImageView> views;
  std::vector<vk::raii::Framebuffer> framebuffers;
  std::vector<vk::raii::Semaphore> rendered;  // per image: presentation waits on its own
  vk::Extent2D extent;
  std::uint32_t min_image_count = 2;
  bool can_capture = false;
  bool stale = true;  // rebuild before the next frame

  Swapchain(gpu::VulkanContext::Impl& c, VkSurfaceKHR raw) : ctx(c), surface(*c.instance, raw) {}

  void wait_idle() {
    if (frame_done && ctx.device->waitForFences(**frame_done, VK_TRUE, std::numeric_limits<std::uint64_t>::max()) !=
                          vk::Result::eSuccess)
      throw std::runtime_error("waiting for the last frame failed");
  }
};

AppWindow::AppWindow(const WindowOptions& options) {
  if (!glfwInit()) throw std::runtime_error("cannot start GLFW: no display? (set DISPLAY, or run under xvfb-run)");
  try {
    open(options);
  } catch (...) {
    shut_down();  // the destructor does not run for a constructor that throws
    throw;
  }
}

void AppWindow::open(const WindowOptions& options) {
  if (!glfwVulkanSupported())
    throw std::runtime_error("GLFW finds no Vulkan loader or no window-system support for Vulkan");
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  window_ = glfwCreateWindow(options.width, options.height, "Paver Studio", nullptr, nullptr);
  if (!window_) throw std::runtime_error("cannot create the window");
  glfwSetWindowUserPointer(window_, this);
  glfwSetDropCallback(window_, [](GLFWwindow* w, int count, const char** paths) {
    auto* self = static_cast<AppWindow*>(glfwGetWindowUserPointer(w));
    for (int i = 0; i < count; ++i) self->dropped_.emplace_back(paths[i]);
  });

  gpu::ContextOptions context_options;
  context_options.graphics = true;
  std::uint32_t count = 0;
  const char** extensions = glfwGetRequiredInstanceExtensions(&count);
  for (std::uint32_t i = 0; i < count; ++i) context_options.instance_extensions.emplace_back(extensions[i]);
  context_options.can_present = [](void* instance, void* physical_device, std::uint32_t family) {
    return glfwGetPhysicalDevicePresentationSupport(static_cast<VkInstance>(instance),
                                                    static_cast<VkPhysicalDevice>(physical_device), family) == GLFW_TRUE;
  };
  auto context = gpu::VulkanContext::create(context_options);
  if (!context) throw std::runtime_error("Vulkan: " + context.error().message);
  context_ = context.value();
  gpu::VulkanContext::Impl& ctx = context_->impl();

  VkSurfaceKHR raw_surface = VK_NULL_HANDLE;
  if (glfwCreateWindowSurface(static_cast<VkInstance>(**ctx.instance), window_, nullptr, &raw_surface) != VK_SUCCESS)
    throw std::runtime_error("cannot create a Vulkan surface for the window");
  swapchain_ = std::make_unique<Swapchain>(ctx, raw_surface);
  Swapchain& s = *swapchain_;
  if (!ctx.physical_device->getSurfaceSupportKHR(ctx.queue_family, *s.surface))
    throw std::runtime_error("the Vulkan device " + context_->device().name + " cannot present to this window");
  s.format = choose_format(ctx.physical_device->getSurfaceFormatsKHR(*s.surface));
  s.present_mode = choose_present_mode(ctx.physical_device->getSurfacePresentModesKHR(*s.surface), options.vsync);

  const vk::AttachmentDescription colour({}, s.format.format, vk::SampleCountFlagBits::e1, vk::AttachmentLoadOp::eClear,
                                         vk::AttachmentStoreOp::eStore, vk::AttachmentLoadOp::eDontCare,
                                         vk::AttachmentStoreOp::eDontCare, vk::ImageLayout::eUndefined,
                                         vk::ImageLayout::ePresentSrcKHR);
  const vk::AttachmentReference reference(0, vk::ImageLayout::eColorAttachmentOptimal);
  const vk::SubpassDescription subpass({}, vk::PipelineBindPoint::eGraphics, {}, reference);
  // The acquire semaphore is waited at colour output: the layout change must wait for it too.
  const vk::SubpassDependency dependency(VK_SUBPASS_EXTERNAL, 0, vk::PipelineStageFlagBits::eColorAttachmentOutput,
                                         vk::PipelineStageFlagBits::eColorAttachmentOutput, {},
                                         vk::AccessFlagBits::eColorAttachmentWrite);
  s.render_pass.emplace(*ctx.device, vk::RenderPassCreateInfo({}, colour, subpass, dependency));
  const vk::DescriptorPoolSize pool_size(vk::DescriptorType::eCombinedImageSampler, 8);
  s.imgui_pool.emplace(*ctx.device,
                       vk::DescriptorPoolCreateInfo(vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet, 8, pool_size));
  vk::raii::CommandBuffers buffers(*ctx.device,
                                   vk::CommandBufferAllocateInfo(**ctx.command_pool, vk::CommandBufferLevel::ePrimary, 1));
  s.commands.emplace(std::move(buffers.front()));
  s.frame_done.emplace(*ctx.device, vk::FenceCreateInfo(vk::FenceCreateFlagBits::eSignaled));
  s.image_acquired.emplace(*ctx.device, vk::SemaphoreCreateInfo());
  rebuild_swapchain();

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // the layout is computed every frame; nothing to remember
  apply_studio_look();  // the font and theme (ImGui's own font where DejaVu Sans is not installed)
  ImGui_ImplGlfw_InitForVulkan(window_, true);
  ImGui_ImplVulkan_InitInfo info{};
  info.Instance = static_cast<VkInstance>(**ctx.instance);
  info.PhysicalDevice = static_cast<VkPhysicalDevice>(**ctx.physical_device);
  info.Device = static_cast<VkDevice>(**ctx.device);
  info.QueueFamily = ctx.queue_family;
  info.Queue = static_cast<VkQueue>(**ctx.queue);
  info.DescriptorPool = static_cast<VkDescriptorPool>(**s.imgui_pool);
  info.MinImageCount = s.min_image_count;
  info.ImageCount = std::uint32_t(s.images.size());
  info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
  info.CheckVkResultFn = check_imgui_vulkan;
  ImGui_ImplVulkan_Init(&info, static_cast<VkRenderPass>(**s.render_pass));
  imgui_ready_ = true;
  ctx.submit_and_wait([](vk::raii::CommandBuffer& cb) { ImGui_ImplVulkan_CreateFontsTexture(static_cast<VkCommandBuffer>(*cb)); });
  ImGui_ImplVulkan_DestroyFontUploadObjects();
  images_ = std::make_unique<ViewImages>(*context_, **s.render_pass);
}

AppWindow::~AppWindow() { shut_down(); }

void AppWindow::shut_down() {
  if (context_ && context_->impl().device) context_->impl().device->waitIdle();
  images_.reset();
  if (imgui_ready_) {
    ImGui_ImplVulkan_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    imgui_ready_ = false;
  }
  swapchain_.reset();  // before the instance the context holds
  context_.reset();
  if (window_) glfwDestroyWindow(window_);
  window_ = nullptr;
  glfwTerminate();
}

bool AppWindow::close_requested() const { return glfwWindowShouldClose(window_); }
void AppWindow::cancel_close() { glfwSetWindowShouldClose(window_, GLFW_FALSE); }
void AppWindow::request_close() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }

std::vector<std::string> AppWindow::take_dropped_paths() { return std::exchange(dropped_, {}); }
bool AppWindow::can_capture() const { return swapchain_->can_capture; }

void AppWindow::rebuild_swapchain() {
  Swapchain& s = *swapchain_;
  gpu::VulkanContext::Impl& ctx = s.ctx;
  ctx.queue->waitIdle();  // presentation too may still wait on the semaphores about to go
  const vk::SurfaceCapabilitiesKHR caps = ctx.physical_device->getSurfaceCapabilitiesKHR(*s.surface);
  int width = 0, height = 0;
  glfwGetFramebufferSize(window_, &width, &height);
  s.extent = caps.currentExtent;
  if (s.extent.width == std::numeric_limits<std::uint32_t>::max())
    s.extent = vk::Extent2D(std::clamp(std::uint32_t(width), caps.minImageExtent.width, caps.maxImageExtent.width),
                            std::clamp(std::uint32_t(height), caps.minImageExtent.height, caps.maxImageExtent.height));
  s.min_image_count = std::max(2u, caps.minImageCount + 1);
  if (caps.maxImageCount > 0) s.min_image_count = std::min(s.min_image_count, caps.maxImageCount);
  s.can_capture = bool(caps.supportedUsageFlags & vk::ImageUsageFlagBits::eTransferSrc);
  const vk::ImageUsageFlags usage =
      vk::ImageUsageFlagBits::eColorAttachment | (s.can_capture ? vk::ImageUsageFlagBits::eTransferSrc : vk::ImageUsageFlags{});
  const vk::CompositeAlphaFlagBitsKHR alpha = caps.supportedCompositeAlpha & vk::CompositeAlphaFlagBitsKHR::eOpaque
                                                  ? vk::CompositeAlphaFlagBitsKHR::eOpaque
                                                  : vk::CompositeAlphaFlagBitsKHR::eInherit;
  const vk::SwapchainCreateInfoKHR info({}, *s.surface, s.min_image_count, s.format.format, s.format.colorSpace, s.extent,
                                        1, usage, vk::SharingMode::eExclusive, {}, caps.currentTransform, alpha,
                                        s.present_mode, VK_TRUE, s.swapchain ? **s.swapchain : vk::SwapchainKHR{});
  s.framebuffers.clear();
  s.views.clear();
  vk::raii::SwapchainKHR swapchain(*ctx.device, info);
  s.swapchain = std::move(swapchain);
  s.images.clear();
  for (const VkImage image : s.swapchain->getImages()) s.images.emplace_back(image);
  s.rendered.clear();
  for (const vk::Image image : s.images) {
    s.views.emplace_back(*ctx.device, vk::ImageViewCreateInfo({}, image, vk::ImageViewType::e2D, s.format.format, {},
                                                              {vk::ImageAspectFlagBits::eColor, 0, 1, 0, 1}));
    s.framebuffers.emplace_back(*ctx.device, vk::FramebufferCreateInfo({}, **s.render_pass, *s.views.back(),
                                                                       s.extent.width, s.extent.height, 1));
    s.rendered.emplace_back(*ctx.device, vk::SemaphoreCreateInfo());
  }
  if (imgui_ready_) ImGui_ImplVulkan_SetMinImageCount(s.min_image_count);
  s.stale = false;
}

bool AppWindow::begin_frame(const InputFrame* input) {
  glfwPollEvents();
  int width = 0, height = 0;
  glfwGetFramebufferSize(window_, &width, &height);
  if (width == 0 || height == 0) {
    glfwWaitEventsTimeout(0.05);
    return false;
  }
  Swapchain& s = *swapchain_;
  if (s.stale || std::uint32_t(width) != s.extent.width || std::uint32_t(height) != s.extent.height)
    rebuild_swapchain();
  // One frame in flight: the renderer may now redraw (and re-create) the images the last frame
  // sampled, and ViewImages may rewrite its descriptor sets.
  s.wait_idle();
  ImGui_ImplVulkan_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGuiIO& io = ImGui::GetIO();
  if (injected_key_ >= 0) io.KeysDown[injected_key_] = false;
  injected_key_ = -1;
  if (!input && injected_) {
    // The backend sets the modifiers only on key events: after a script's input they are the
    // real keys' again, as its key callback would set them.
    io.KeyCtrl = io.KeysDown[GLFW_KEY_LEFT_CONTROL] || io.KeysDown[GLFW_KEY_RIGHT_CONTROL];
    io.KeyShift = io.KeysDown[GLFW_KEY_LEFT_SHIFT] || io.KeysDown[GLFW_KEY_RIGHT_SHIFT];
  }
  injected_ = input != nullptr;
  if (input) {  // after the backend, so that this frame's state is the script's
    io.MousePos = ImVec2(input->mouse.x, input->mouse.y);
    io.MouseDown[ImGuiMouseButton_Left] = input->left_down;
    io.KeyShift = input->shift;
    io.KeyCtrl = input->ctrl;
    if (input->key >= 0) io.KeysDown[injected_key_ = input->key] = true;
    if (!input->text.empty()) io.AddInputCharactersUTF8(input->text.c_str());
  }
  ImGui::NewFrame();
  return true;
}

std::optional<render::Image> AppWindow::end_frame(bool capture) {
  ImGui::Render();
  ImDrawData* draw_data = ImGui::GetDrawData();
  Swapchain& s = *swapchain_;
  gpu::VulkanContext::Impl& ctx = s.ctx;

  std::uint32_t index = 0;
  try {
    const auto [result, acquired] =
        s.swapchain->acquireNextImage(std::numeric_limits<std::uint64_t>::max(), **s.image_acquired);
    if (result == vk::Result::eSuboptimalKHR) s.stale = true;
    index = acquired;
  } catch (const vk::OutOfDateKHRError&) {
    s.stale = true;
    return std::nullopt;
  }

  capture = capture && s.can_capture;
  std::optional<gpu::GpuBuffer> pixels;
  if (capture)
    pixels.emplace(ctx, vk::DeviceSize(s.extent.width) * s.extent.height * 4, vk::BufferUsageFlagBits::eTransferDst,
                   vk::MemoryPropertyFlagBits::eHostVisible | vk::MemoryPropertyFlagBits::eHostCoherent,
                   vk::MemoryPropertyFlags{});
  const vk::Image image = s.images[index];

  vk::raii::CommandBuffer& cb = *s.commands;
  cb.reset();
  cb.begin(vk::CommandBufferBeginInfo(vk::CommandBufferUsageFlagBits::eOneTimeSubmit));
  // The renderer drew its views in earlier submissions; make those writes visible to sampling.
  const vk::MemoryBarrier drawn(vk::AccessFlagBits::eColorAttachmentWrite, vk::AccessFlagBits::eShaderRead);
  cb.pipelineBarrier(vk::PipelineStageFlagBits::eColorAttachmentOutput, vk::PipelineStageFlagBits::eFragmentShader, {},
                     drawn, {}, {});
  const vk::ClearValue clear(vk::ClearColorValue(std::array<float, 4>{0.10f, 0.10f, 0.11f, 1.0f}));
  cb.beginRenderPass(vk::RenderPassBeginInfo(**s.render_pass, *s.framebuffers[index], vk::Rect2D({0, 0}, s.extent), clear),
                     vk::SubpassContents::eInline);
  images_->set_command_buffer(&cb);
  ImGui_ImplVulkan_RenderDrawData(draw_data, static_cast<VkCommandBuffer>(*cb));
  images_->set_command_buffer(nullptr);
  cb.endRenderPass();
  if (capture) {
    const vk::ImageSubresourceRange range(vk::ImageAspectFlagBits::eColor, 0, 1, 0, 1);
    cb.pipelineBarrier(vk::PipelineStageFlagBits::eColorAttachmentOutput, vk::PipelineStageFlagBits::eTransfer, {}, {},
                       {},
                       vk::ImageMemoryBarrier(vk::AccessFlagBits::eColorAttachmentWrite, vk::AccessFlagBits::eTransferRead,
                                              vk::ImageLayout::ePresentSrcKHR, vk::ImageLayout::eTransferSrcOptimal,
                                              VK_QUEUE_FAMILY_IGNORED, VK_QUEUE_FAMILY_IGNORED, image, range));
    cb.copyImageToBuffer(image, vk::ImageLayout::eTransferSrcOptimal, pixels->handle(),
                         vk::BufferImageCopy(0, 0, 0, {vk::ImageAspectFlagBits::eColor, 0, 0, 1}, {0, 0, 0},
                                             vk::Extent3D(s.extent, 1)));
    // The image goes back to presentation; the copied pixels are made visible to the host.
    cb.pipelineBarrier(vk::PipelineStageFlagBits::eTransfer,
                       vk::PipelineStageFlagBits::eBottomOfPipe | vk::PipelineStageFlagBits::eHost, {}, {},
                       vk::BufferMemoryBarrier(vk::AccessFlagBits::eTransferWrite, vk::AccessFlagBits::eHostRead,
                                               VK_QUEUE_FAMILY_IGNORED, VK_QUEUE_FAMILY_IGNORED, pixels->handle(), 0,
                                               VK_WHOLE_SIZE),
                       vk::ImageMemoryBarrier(vk::AccessFlagBits::eTransferRead, {}, vk::ImageLayout::eTransferSrcOptimal,
                                              vk::ImageLayout::ePresentSrcKHR, VK_QUEUE_FAMILY_IGNORED,
                                              VK_QUEUE_FAMILY_IGNORED, image, range));
  }
  cb.end();

  ctx.device->resetFences(**s.frame_done);
  const vk::PipelineStageFlags wait_stage = vk::PipelineStageFlagBits::eColorAttachmentOutput;
  const vk::Semaphore acquired = **s.image_acquired;
  const vk::CommandBuffer raw = *cb;
  const vk::Semaphore rendered = *s.rendered[index];
  ctx.queue->submit(vk::SubmitInfo(acquired, wait_stage, raw, rendered), **s.frame_done);
  try {
    if (ctx.queue->presentKHR(vk::PresentInfoKHR(rendered, **s.swapchain, index)) == vk::Result::eSuboptimalKHR)
      s.stale = true;
  } catch (const vk::OutOfDateKHRError&) {
    s.stale = true;
  }
  if (!capture) return std::nullopt;

  s.wait_idle();
  render::Image shot;
  shot.width = int(s.extent.width);
  shot.height = int(s.extent.height);
  shot.rgba.resize(std::size_t(shot.width) * shot.height * 4);
  const auto* source = static_cast<const std::uint8_t*>(pixels->mapped());
  const bool bgra = s.format.format == vk::Format::eB8G8R8A8Unorm || s.format.format == vk::Format::eB8G8R8A8Srgb;
  for (std::size_t i = 0; i < shot.rgba.size(); i += 4) {
    shot.rgba[i + 0] = source[i + (bgra ? 2 : 0)];
    shot.rgba[i + 1] = source[i + 1];
    shot.rgba[i + 2] = source[i + (bgra ? 0 : 2)];
    shot.rgba[i + 3] = 255;  // the window is opaque whatever the alpha channel holds
  }
  return shot;
}

}  // namespace paver::studio
