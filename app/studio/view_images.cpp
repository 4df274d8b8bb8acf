#include "view_images.h"

#include "renderer.h"

#include "paver/compute/vulkan_objects.h"

#include <cstddef>
#include <cstdint>

// SPIR-V embedded at build time (app/CMakeLists.txt).
#include "studio_image_frag_spv.h"
#include "studio_image_vert_spv.h"

namespace paver::studio {

ViewImages::ViewImages(gpu::VulkanContext& context, vk::RenderPass render_pass)
    : device_(*context.impl().device), bindings_{{{this, 0}, {this, 1}}} {
  const vk::DescriptorSetLayoutBinding binding(0, vk::DescriptorType::eCombinedImageSampler, 1,
                                               vk::ShaderStageFlagBits::eFragment);
  set_layout_.emplace(device_, vk::DescriptorSetLayoutCreateInfo({}, binding));
  const vk::PushConstantRange push(vk::ShaderStageFlagBits::eVertex, 0, 4 * sizeof(float));
  const vk::DescriptorSetLayout set_layout = **set_layout_;
  layout_.emplace(device_, vk::PipelineLayoutCreateInfo({}, set_layout, push));

  const vk::raii::ShaderModule vert(device_, vk::ShaderModuleCreateInfo({}, sizeof(studio_image_vert_spv),
                                                                        studio_image_vert_spv));
  const vk::raii::ShaderModule frag(device_, vk::ShaderModuleCreateInfo({}, sizeof(studio_image_frag_spv),
                                                                        studio_image_frag_spv));
  const vk::PipelineShaderStageCreateInfo stages[] = {
      {{}, vk::ShaderStageFlagBits::eVertex, *vert, "main"}, {{}, vk::ShaderStageFlagBits::eFragment, *frag, "main"}};
  const vk::VertexInputBindingDescription vertex_binding(0, sizeof(ImDrawVert), vk::VertexInputRate::eVertex);
  const vk::VertexInputAttributeDescription attributes[] = {
      {0, 0, vk::Format::eR32G32Sfloat, offsetof(ImDrawVert, pos)},
      {1, 0, vk::Format::eR32G32Sfloat, offsetof(ImDrawVert, uv)},
      {2, 0, vk::Format::eR8G8B8A8Unorm, offsetof(ImDrawVert, col)}};
  const vk::PipelineVertexInputStateCreateInfo input({}, vertex_binding, attributes);
  const vk::PipelineInputAssemblyStateCreateInfo assembly({}, vk::PrimitiveTopology::eTriangleList);
  const vk::PipelineViewportStateCreateInfo viewport({}, 1, nullptr, 1, nullptr);
  vk::PipelineRasterizationStateCreateInfo raster;
  raster.lineWidth = 1;
  const vk::PipelineMultisampleStateCreateInfo multisample;
  vk::PipelineColorBlendAttachmentState blend;
  blend.colorWriteMask = vk::ColorComponentFlagBits::eR | vk::ColorComponentFlagBits::eG |
                         vk::ColorComponentFlagBits::eB | vk::ColorComponentFlagBits::eA;
  const vk::PipelineColorBlendStateCreateInfo colour({}, false, vk::LogicOp::eCopy, blend);
  const vk::DynamicState dynamic[] = {vk::DynamicState::eViewport, vk::DynamicState::eScissor};
  const vk::PipelineDynamicStateCreateInfo dynamic_state({}, dynamic);
  const vk::GraphicsPipelineCreateInfo info({}, stages, &input, &assembly, nullptr, &viewport, &raster, &multisample,
                                            nullptr, &colour, &dynamic_state, **layout_, render_pass, 0);
  pipeline_.emplace(device_, nullptr, info);

  const vk::DescriptorPoolSize size(vk::DescriptorType::eCombinedImageSampler, 2);
  pool_.emplace(device_, vk::DescriptorPoolCreateInfo(vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet, 2, size));
  const vk::DescriptorSetLayout layouts[] = {set_layout, set_layout};
  sets_.emplace(device_, vk::DescriptorSetAllocateInfo(**pool_, layouts));
}

void ViewImages::image(const render::Renderer& renderer, int view, ImVec2 size) {
  const vk::raii::DescriptorSet& set = (*sets_)[view];
  // The renderer re-creates a view's image when its size changes; no frame is in flight here
  // (begin_frame waited), so the set can be rewritten.
  if (generation_[view] != renderer.image_generation(view)) {
    const vk::DescriptorImageInfo image(static_cast<VkSampler>(renderer.sampler()),
                                        static_cast<VkImageView>(renderer.image_view(view)),
                                        vk::ImageLayout::eShaderReadOnlyOptimal);
    device_.updateDescriptorSets(vk::WriteDescriptorSet(*set, 0, 0, vk::DescriptorType::eCombinedImageSampler, image),
                                 {});
    generation_[view] = renderer.image_generation(view);
  }
  ImDrawList* list = ImGui::GetWindowDrawList();
  list->AddCallback(&ViewImages::bind_view, &bindings_[view]);
  ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<VkDescriptorSet>(*set)), size);
  list->AddCallback(ImDrawCallback_ResetRenderState, nullptr);
}

void ViewImages::bind_view(const ImDrawList*, const ImDrawCmd* cmd) {
  const auto* binding = static_cast<const Binding*>(cmd->UserCallbackData);
  ViewImages& self = *binding->self;
  if (!self.command_buffer_) return;
  vk::raii::CommandBuffer& cb = *self.command_buffer_;
  const ImDrawData* data = ImGui::GetDrawData();
  cb.bindPipeline(vk::PipelineBindPoint::eGraphics, **self.pipeline_);
  cb.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, **self.layout_, 0, *(*self.sets_)[binding->view], {});
  cb.setViewport(0, vk::Viewport(0, 0, data->DisplaySize.x * data->FramebufferScale.x,
                                 data->DisplaySize.y * data->FramebufferScale.y, 0, 1));
  // ImGui's mapping from display coordinates to clip space, as the backend pushes it.
  const float scale[2] = {2.0f / data->DisplaySize.x, 2.0f / data->DisplaySize.y};
  const float push[4] = {scale[0], scale[1], -1.0f - data->DisplayPos.x * scale[0],
                         -1.0f - data->DisplayPos.y * scale[1]};
  cb.pushConstants<float>(**self.layout_, vk::ShaderStageFlagBits::eVertex, 0, push);
}

}  // namespace paver::studio
