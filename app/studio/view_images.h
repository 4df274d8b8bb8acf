#pragma once
// The renderer's offscreen views shown as ImGui images. ImGui 1.86's Vulkan backend binds only
// its font texture, once per frame, and ignores ImTextureID (ImGui_ImplVulkan_AddTexture and
// per-command binding came in 1.87). So each view is drawn between two draw-list callbacks: the
// first binds a pipeline of ours (the backend's vertex layout and push constants, sampling a
// texture) with the view's descriptor set, the second hands the state back to the backend.
#include <imgui.h>

#include <vulkan/vulkan_raii.hpp>

#include <array>
#include <optional>

namespace paver::render {
class Renderer;
}
namespace paver::gpu {
class VulkanContext;
}

namespace paver::studio {

class ViewImages {
public:
  ViewImages(gpu::VulkanContext& context, vk::RenderPass render_pass);
  ViewImages(const ViewImages&) = delete;
  ViewImages& operator=(const ViewImages&) = delete;

  // An image item of `size` at the cursor showing the renderer's view (0: 3D, 1: 2D), which
  // must have been rendered. Call between the window's begin_frame and end_frame.
  void image(const render::Renderer& renderer, int view, ImVec2 size);

  // The command buffer ImGui's draw data is being recorded into (the window sets it).
  void set_command_buffer(vk::raii::CommandBuffer* cb) { command_buffer_ = cb; }

private:
  struct Binding {
    ViewImages* self;
    int view;
  };
  static void bind_view(const ImDrawList* list, const ImDrawCmd* cmd);

  const vk::raii::Device& device_;
  std::optional<vk::raii::DescriptorSetLayout> set_layout_;
  std::optional<vk::raii::PipelineLayout> layout_;
  std::optional<vk::raii::Pipeline> pipeline_;
  std::optional<vk::raii::DescriptorPool> pool_;
  std::optional<vk::raii::DescriptorSets> sets_;
  std::array<int, 2> generation_{-1, -1};  // the renderer image each set points at
  std::array<Binding, 2> bindings_;
  vk::raii::CommandBuffer* command_buffer_ = nullptr;
};

}  // namespace paver::studio
