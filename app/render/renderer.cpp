#include "renderer.h"

#include "element_instance.h"

#include "core/contact_rule.h"

#include "paver/compute/gpu_buffer.h"
#include "paver/compute/vulkan_objects.h"
#include "elements/element_proximity.h"
#include "map/lifting.h"
#include "mesh/mean_curvature.h"
#include "report/pavement_quality.h"
#include "render_targets.h"
#include "scene_data.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <chrono>
#include <functional>
#include <limits>
#include <map>
#include <span>
// SPIR-V embedded at build time (app/render/CMakeLists.txt).
#include "disk_frag_spv.h"
#include "disk_vert_spv.h"
#include "element_frag_spv.h"
#include "element_vert_spv.h"
#include "flat_frag_spv.h"
#include "flat_vert_spv.h"
#include "surface_frag_spv.h"
#include "surface_vert_spv.h"

namespace paver::render {
namespace {

struct FramePush {
  glm::mat4 view_projection;
  glm::vec4 eye;
  glm::vec4 light;
};
static_assert(sizeof(FramePush) == 96);

struct SurfaceVertex {
  glm::vec3 position, normal;
};

// One draw of a view's image, or a run of its instances: what a slice of the drawing records, and
// its cost in vertices.
struct DrawPiece {
  std::function<void(vk::raii::CommandBuffer&)> record;
  std::uint64_t vertices = 0;
};

// A view's image drawn in pieces: one submission draws pieces of up to kSliceVertices (one at
// least) into the image; the first clears it, the later ones add to it. On lavapipe, with the
// solver on the other core, 40,000 vertices take a few milliseconds.
constexpr std::uint64_t kSliceVertices = 40000;
constexpr double kWholeImage = std::numeric_limits<double>::infinity();

struct ViewDrawing {
  std::vector<DrawPiece> pieces;
  std::size_t next = 0;  // the first piece not drawn yet
  bool cleared = false;  // the first slice (clear) was drawn
  FramePush push{};
  SceneStyle style;
};

}  // namespace

struct Renderer::Impl {
  std::shared_ptr<gpu::VulkanContext> context;
  gpu::VulkanContext::Impl* vk = nullptr;
  std::optional<vk::raii::RenderPass> pass;
  std::optional<vk::raii::RenderPass> pass_again;  // draws onto what the earlier slices drew
  std::optional<vk::raii::PipelineLayout> layout;
  std::optional<vk::raii::Pipeline> surface_pipe, element_pipe, lines3d_pipe, tris2d_pipe, lines2d_pipe, disk_pipe;
  std::optional<vk::raii::Sampler> sampler;
  // Per view: the full image shown, the one drawn over several frames (start_drawing, draw_more)
  // until it is complete and takes the other's place, and [2] the quick image (render_quick).
  std::array<std::array<RenderTarget, 3>, 2> targets;
  std::array<int, 2> shown{0, 0};             // the full image shown: 0 or 1
  std::array<bool, 2> quick_shown{false, false};  // the quick image is shown instead
  std::array<int, 2> image_changes{0, 0};  // the shown image re-created or swapped
  std::array<std::optional<ViewDrawing>, 2> unfinished;

  // Scene buffers (host-visible: rewritten whenever the scene changes).
  gpu::GpuBuffer surface_vertices, surface_indices, map_triangles, map_lines, shape_vertices, instances,
      lattice3d, lattice2d, disks;
  std::uint32_t surface_index_count = 0, map_triangle_count = 0, map_line_count = 0, lattice3d_count = 0,
                lattice2d_count = 0, disk_count = 0;
  std::map<ShapeKind, DrawRange> shape_range;     // vertices
  std::map<ShapeKind, DrawRange> instance_range;  // instances

  vk::raii::ShaderModule module(std::span<const std::uint32_t> spirv) {
    return vk::raii::ShaderModule(*vk->device, vk::ShaderModuleCreateInfo({}, spirv.size_bytes(), spirv.data()));
  }

  void create() {
    // Depth is kept: a later slice of the image tests against what the earlier ones drew.
    vk::AttachmentDescription attachments[] = {
        {{}, kColourFormat, vk::SampleCountFlagBits::e1, vk::AttachmentLoadOp::eClear, vk::AttachmentStoreOp::eStore,
         vk::AttachmentLoadOp::eDontCare, vk::AttachmentStoreOp::eDontCare, vk::ImageLayout::eUndefined,
         vk::ImageLayout::eShaderReadOnlyOptimal},
        {{}, kDepthFormat, vk::SampleCountFlagBits::e1, vk::AttachmentLoadOp::eClear, vk::AttachmentStoreOp::eStore,
         vk::AttachmentLoadOp::eDontCare, vk::AttachmentStoreOp::eDontCare, vk::ImageLayout::eUndefined,
         vk::ImageLayout::eDepthStencilAttachmentOptimal}};
    const vk::AttachmentReference colour_ref(0, vk::ImageLayout::eColorAttachmentOptimal);
    const vk::AttachmentReference depth_ref(1, vk::ImageLayout::eDepthStencilAttachmentOptimal);
    const vk::SubpassDescription subpass({}, vk::PipelineBindPoint::eGraphics, {}, colour_ref, {}, &depth_ref);
    // Earlier samplings/copies of the image, and the drawing of an earlier slice of it, finish
    // before we draw; later ones (the studio's ImGui pass, a PNG copy) wait for the drawing.
    const vk::SubpassDependency dependencies[] = {
        {VK_SUBPASS_EXTERNAL, 0,
         vk::PipelineStageFlagBits::eFragmentShader | vk::PipelineStageFlagBits::eTransfer |
             vk::PipelineStageFlagBits::eColorAttachmentOutput | vk::PipelineStageFlagBits::eEarlyFragmentTests |
             vk::PipelineStageFlagBits::eLateFragmentTests,
         vk::PipelineStageFlagBits::eColorAttachmentOutput | vk::PipelineStageFlagBits::eEarlyFragmentTests |
             vk::PipelineStageFlagBits::eLateFragmentTests,
         vk::AccessFlagBits::eShaderRead | vk::AccessFlagBits::eTransferRead | vk::AccessFlagBits::eColorAttachmentWrite |
             vk::AccessFlagBits::eDepthStencilAttachmentWrite,
         vk::AccessFlagBits::eColorAttachmentRead | vk::AccessFlagBits::eColorAttachmentWrite |
             vk::AccessFlagBits::eDepthStencilAttachmentRead | vk::AccessFlagBits::eDepthStencilAttachmentWrite},
        {0, VK_SUBPASS_EXTERNAL, vk::PipelineStageFlagBits::eColorAttachmentOutput,
         vk::PipelineStageFlagBits::eFragmentShader | vk::PipelineStageFlagBits::eTransfer,
         vk::AccessFlagBits::eColorAttachmentWrite, vk::AccessFlagBits::eShaderRead | vk::AccessFlagBits::eTransferRead}};
    pass.emplace(*vk->device, vk::RenderPassCreateInfo({}, attachments, subpass, dependencies));
    for (auto& a : attachments) a.loadOp = vk::AttachmentLoadOp::eLoad;
    attachments[0].initialLayout = vk::ImageLayout::eShaderReadOnlyOptimal;
    attachments[1].initialLayout = vk::ImageLayout::eDepthStencilAttachmentOptimal;
    pass_again.emplace(*vk->device, vk::RenderPassCreateInfo({}, attachments, subpass, dependencies));
    const vk::PushConstantRange push(vk::ShaderStageFlagBits::eVertex | vk::ShaderStageFlagBits::eFragment, 0,
                                     sizeof(FramePush));
    layout.emplace(*vk->device, vk::PipelineLayoutCreateInfo({}, {}, push));
    sampler.emplace(*vk->device, vk::SamplerCreateInfo({}, vk::Filter::eLinear, vk::Filter::eLinear,
                                                       vk::SamplerMipmapMode::eNearest,
                                                       vk::SamplerAddressMode::eClampToEdge,
                                                       vk::SamplerAddressMode::eClampToEdge,
                                                       vk::SamplerAddressMode::eClampToEdge));

    using B = vk::VertexInputBindingDescription;
    using A = vk::VertexInputAttributeDescription;
    const B surface_b[] = {{0, sizeof(SurfaceVertex), vk::VertexInputRate::eVertex}};
    const A surface_a[] = {{0, 0, vk::Format::eR32G32B32Sfloat, 0},
                           {1, 0, vk::Format::eR32G32B32Sfloat, offsetof(SurfaceVertex, normal)}};
    surface_pipe.emplace(make_pipeline(surface_vert_spv, surface_frag_spv, surface_b, surface_a,
                                       vk::PrimitiveTopology::eTriangleList, true));
    const B element_b[] = {{0, sizeof(glm::vec3), vk::VertexInputRate::eVertex},
                           {1, sizeof(ElementInstance), vk::VertexInputRate::eInstance}};
    const A element_a[] = {{0, 0, vk::Format::eR32G32B32Sfloat, 0},
                           {1, 1, vk::Format::eR32G32B32Sfloat, offsetof(ElementInstance, centre)},
                           {2, 1, vk::Format::eR32G32B32Sfloat, offsetof(ElementInstance, normal)},
                           {3, 1, vk::Format::eR32Sfloat, offsetof(ElementInstance, diameter)},
                           {4, 1, vk::Format::eR8G8B8A8Unorm, offsetof(ElementInstance, colour)},
                           {5, 1, vk::Format::eR32G32B32Sfloat, offsetof(ElementInstance, tangent)},
                           {6, 1, vk::Format::eR32G32B32Sfloat, offsetof(ElementInstance, bitangent)}};
    element_pipe.emplace(make_pipeline(element_vert_spv, element_frag_spv, element_b, element_a,
                                       vk::PrimitiveTopology::eTriangleList, true));
    const B flat_b[] = {{0, sizeof(FlatVertex), vk::VertexInputRate::eVertex}};
    const A flat_a[] = {{0, 0, vk::Format::eR32G32B32Sfloat, 0},
                        {1, 0, vk::Format::eR8G8B8A8Unorm, offsetof(FlatVertex, colour)}};
    lines3d_pipe.emplace(make_pipeline(flat_vert_spv, flat_frag_spv, flat_b, flat_a, vk::PrimitiveTopology::eLineList, true));
    tris2d_pipe.emplace(make_pipeline(flat_vert_spv, flat_frag_spv, flat_b, flat_a, vk::PrimitiveTopology::eTriangleList, false));
    lines2d_pipe.emplace(make_pipeline(flat_vert_spv, flat_frag_spv, flat_b, flat_a, vk::PrimitiveTopology::eLineList, false));
    const B disk_b[] = {{0, sizeof(DiskInstance), vk::VertexInputRate::eInstance}};
    const A disk_a[] = {{0, 0, vk::Format::eR32G32Sfloat, offsetof(DiskInstance, centre)},
                        {1, 0, vk::Format::eR32Sfloat, offsetof(DiskInstance, radius)},
                        {2, 0, vk::Format::eR8G8B8A8Unorm, offsetof(DiskInstance, colour)}};
    disk_pipe.emplace(make_pipeline(disk_vert_spv, disk_frag_spv, disk_b, disk_a, vk::PrimitiveTopology::eTriangleList, false));
  }

  vk::raii::Pipeline make_pipeline(std::span<const std::uint32_t> vert, std::span<const std::uint32_t> frag,
                                   std::span<const vk::VertexInputBindingDescription> bindings,
                                   std::span<const vk::VertexInputAttributeDescription> attributes,
                                   vk::PrimitiveTopology topology, bool depth) {
    const vk::raii::ShaderModule vs = module(vert), fs = module(frag);
    const vk::PipelineShaderStageCreateInfo stages[] = {{{}, vk::ShaderStageFlagBits::eVertex, *vs, "main"},
                                                        {{}, vk::ShaderStageFlagBits::eFragment, *fs, "main"}};
    const vk::PipelineVertexInputStateCreateInfo input({}, std::uint32_t(bindings.size()), bindings.data(),
                                                       std::uint32_t(attributes.size()), attributes.data());
    const vk::PipelineInputAssemblyStateCreateInfo assembly({}, topology);
    const vk::PipelineViewportStateCreateInfo viewport({}, 1, nullptr, 1, nullptr);
    // Lines in 3D sit a hair in front of the surface they were lifted onto.
    const bool lines = topology == vk::PrimitiveTopology::eLineList;
    const vk::PipelineRasterizationStateCreateInfo raster({}, false, false, vk::PolygonMode::eFill, vk::CullModeFlagBits::eNone,
                                                          vk::FrontFace::eCounterClockwise, false, 0, 0, 0, 1.0f);
    const vk::PipelineMultisampleStateCreateInfo multisample({}, vk::SampleCountFlagBits::e1);
    const vk::PipelineDepthStencilStateCreateInfo depth_state({}, depth, depth && !lines, vk::CompareOp::eLessOrEqual);
    const vk::PipelineColorBlendAttachmentState blend(false, {}, {}, {}, {}, {}, {},
                                                      vk::ColorComponentFlagBits::eR | vk::ColorComponentFlagBits::eG |
                                                          vk::ColorComponentFlagBits::eB | vk::ColorComponentFlagBits::eA);
    const vk::PipelineColorBlendStateCreateInfo blending({}, false, vk::LogicOp::eCopy, blend);
    const vk::DynamicState dynamic[] = {vk::DynamicState::eViewport, vk::DynamicState::eScissor};
    const vk::PipelineDynamicStateCreateInfo dynamic_state({}, dynamic);
    const vk::GraphicsPipelineCreateInfo info({}, stages, &input, &assembly, nullptr, &viewport, &raster, &multisample,
                                              &depth_state, &blending, &dynamic_state, **layout, **pass, 0);
    return vk::raii::Pipeline(*vk->device, nullptr, info);
  }

  template <class T>
  gpu::GpuBuffer host_buffer(const std::vector<T>& data, vk::BufferUsageFlags usage) {
    gpu::GpuBuffer b(*vk, std::max<std::size_t>(data.size() * sizeof(T), 16), usage,
                     vk::MemoryPropertyFlagBits::eHostVisible | vk::MemoryPropertyFlagBits::eHostCoherent, {});
    if (!data.empty()) std::memcpy(b.mapped(), data.data(), data.size() * sizeof(T));
    return b;
  }

  void begin(vk::raii::CommandBuffer& cb, RenderTarget& t, const SceneStyle& style, bool clear) {
    const vk::ClearValue clears[] = {vk::ClearColorValue(std::array<float, 4>{style.background[0], style.background[1],
                                                                               style.background[2], 1.0f}),
                                     vk::ClearDepthStencilValue(1.0f, 0)};
    // The framebuffer was made with `pass`; `pass_again` is compatible with it.
    cb.beginRenderPass(vk::RenderPassBeginInfo(clear ? **pass : **pass_again, **t.framebuffer,
                                               vk::Rect2D({0, 0}, {std::uint32_t(t.width), std::uint32_t(t.height)}), clears),
                       vk::SubpassContents::eInline);
    // Flip y so +y is up, as in the maps and the camera.
    cb.setViewport(0, vk::Viewport(0, float(t.height), float(t.width), -float(t.height), 0, 1));
    cb.setScissor(0, vk::Rect2D({0, 0}, {std::uint32_t(t.width), std::uint32_t(t.height)}));
  }

  void push(vk::raii::CommandBuffer& cb, const FramePush& f) {
    cb.pushConstants<FramePush>(**layout, vk::ShaderStageFlagBits::eVertex | vk::ShaderStageFlagBits::eFragment, 0, f);
  }

  RenderTarget& shown_target(int view) { return targets[view][quick_shown[view] ? 2 : shown[view]]; }
  RenderTarget& drawn_target(int view) { return targets[view][1 - shown[view]]; }

  // Draws slices of `drawing` into `t` until it is complete or `budget_ms` is spent (one slice at
  // least); returns true once it is complete.
  bool draw_slices(RenderTarget& t, ViewDrawing& drawing, double budget_ms) {
    const auto start = std::chrono::steady_clock::now();
    const std::vector<DrawPiece>& pieces = drawing.pieces;
    const bool whole = budget_ms == kWholeImage;
    do {
      std::size_t end = drawing.next;
      std::uint64_t vertices = 0;
      while (end < pieces.size() && (whole || end == drawing.next || vertices + pieces[end].vertices <= kSliceVertices))
        vertices += pieces[end++].vertices;
      vk->submit_and_wait([&](vk::raii::CommandBuffer& cb) {
        begin(cb, t, drawing.style, !drawing.cleared);
        push(cb, drawing.push);
        for (std::size_t i = drawing.next; i < end; ++i) pieces[i].record(cb);
        cb.endRenderPass();
      });
      drawing.cleared = true;
      drawing.next = end;
    } while (drawing.next < pieces.size() &&
             std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() < budget_ms);
    return drawing.next == pieces.size();
  }

  // One draw of `count` vertices of `buffer` (FlatVertex) with `pipe`: lines and map triangles.
  static DrawPiece flat_piece(const vk::raii::Pipeline& pipe, const gpu::GpuBuffer& buffer, std::uint32_t count) {
    return {[&pipe, &buffer, count](vk::raii::CommandBuffer& cb) {
              cb.bindPipeline(vk::PipelineBindPoint::eGraphics, *pipe);
              cb.bindVertexBuffers(0, buffer.handle(), {0});
              cb.draw(count, 1, 0, 0);
            },
            count};
  }

  // A run of instanced draws cut so that each piece stays within a slice.
  void add_instanced(std::vector<DrawPiece>& pieces, const std::function<void(vk::raii::CommandBuffer&)>& bind,
                     std::uint32_t shape_first, std::uint32_t shape_vertices, std::uint32_t first, std::uint32_t count) {
    const std::uint32_t per_piece = std::uint32_t(std::max<std::uint64_t>(1, kSliceVertices / std::max(1u, shape_vertices)));
    for (std::uint32_t at = first; at < first + count; at += per_piece) {
      const std::uint32_t n = std::min(per_piece, first + count - at);
      pieces.push_back({[=](vk::raii::CommandBuffer& cb) {
                          bind(cb);
                          cb.draw(shape_vertices, n, shape_first, at);
                        },
                        std::uint64_t(shape_vertices) * n});
    }
  }

  ViewDrawing drawing_3d(const RenderTarget& t, const OrbitCamera& camera, const SceneStyle& style) {
    ViewDrawing out;
    out.style = style;
    out.push = FramePush{camera.view_projection(float(t.width) / float(t.height)), glm::vec4(camera.eye(), 1),
                         glm::vec4(glm::normalize(camera.eye() - camera.target) + glm::vec3(0.3f, 0.2f, 0.8f), 0)};
    if (style.show_surface && surface_index_count > 0)
      out.pieces.push_back({[this](vk::raii::CommandBuffer& cb) {
                              cb.bindPipeline(vk::PipelineBindPoint::eGraphics, **surface_pipe);
                              cb.bindVertexBuffers(0, surface_vertices.handle(), {0});
                              cb.bindIndexBuffer(surface_indices.handle(), 0, vk::IndexType::eUint32);
                              cb.drawIndexed(surface_index_count, 1, 0, 0, 0);
                            },
                            surface_index_count});
    if (style.show_elements) {
      const auto bind = [this](vk::raii::CommandBuffer& cb) {
        cb.bindPipeline(vk::PipelineBindPoint::eGraphics, **element_pipe);
        cb.bindVertexBuffers(0, {shape_vertices.handle(), instances.handle()}, {0, 0});
      };
      for (const auto& [kind, range] : instance_range) {
        if (range.second == 0) continue;
        const auto shape = shape_range.at(kind);
        add_instanced(out.pieces, bind, shape.first, shape.second, range.first, range.second);
      }
    }
    if (style.show_lattice && lattice3d_count > 0) out.pieces.push_back(flat_piece(*lines3d_pipe, lattice3d, lattice3d_count));
    return out;
  }

  ViewDrawing drawing_2d(const RenderTarget& t, const MapView& view, const SceneStyle& style) {
    ViewDrawing out;
    out.style = style;
    out.push = FramePush{view.projection(float(t.width) / float(t.height)), glm::vec4(0, 0, 1, 1), glm::vec4(0, 0, 1, 0)};
    if (map_triangle_count > 0) out.pieces.push_back(flat_piece(*tris2d_pipe, map_triangles, map_triangle_count));
    if (style.show_map_wireframe && map_line_count > 0)
      out.pieces.push_back(flat_piece(*lines2d_pipe, map_lines, map_line_count));
    if (style.show_lattice && lattice2d_count > 0) out.pieces.push_back(flat_piece(*lines2d_pipe, lattice2d, lattice2d_count));
    if (style.show_elements && disk_count > 0)
      add_instanced(out.pieces,
                    [this](vk::raii::CommandBuffer& cb) {
                      cb.bindPipeline(vk::PipelineBindPoint::eGraphics, **disk_pipe);
                      cb.bindVertexBuffers(0, disks.handle(), {0});
                    },
                    0, 6, 0, disk_count);
    return out;
  }

  ViewDrawing drawing_of(int view, const RenderTarget& t, const ViewRequest& request) {
    return view == 0 ? drawing_3d(t, request.camera, request.style) : drawing_2d(t, request.map_view, request.style);
  }
};

glm::mat4 OrbitCamera::view_projection(float aspect) const {
  const glm::mat4 view = glm::lookAt(eye(), target, glm::vec3(0, 0, 1));
  const glm::mat4 proj = glm::perspective(glm::radians(fov_deg), aspect, 0.01f * distance, 100.0f * distance);
  return glm::translate(glm::mat4(1), glm::vec3(screen_shift_x, 0, 0)) * proj * view;
}

glm::vec3 OrbitCamera::eye() const {
  const float p = std::clamp(pitch, -1.5f, 1.5f);
  return target + distance * glm::vec3(std::cos(p) * std::cos(yaw), std::cos(p) * std::sin(yaw), std::sin(p));
}

OrbitCamera frame_surface(const SurfaceMesh& mesh, double aspect, double right_share) {
  glm::dvec3 lo(1e300), hi(-1e300), normal_sum(0);
  for (const auto& p : mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  double area = 0;
  for (const auto& t : mesh.triangles) {
    const glm::dvec3 n = glm::cross(mesh.positions[t.y] - mesh.positions[t.x], mesh.positions[t.z] - mesh.positions[t.x]);
    normal_sum += n;
    area += glm::length(n);
  }
  OrbitCamera c;
  c.target = glm::vec3(0.5 * (lo + hi));
  // The sphere around the bounding box's centre that holds every point: tighter than the box.
  double radius = 0;
  for (const auto& p : mesh.positions) radius = std::max(radius, glm::length(p - glm::dvec3(c.target)));
  c.distance = float(radius) / std::sin(glm::radians(c.fov_deg) * 0.5f);
  // The fov is vertical: a free part narrower than high moves the camera back until it fits across.
  const double share = std::clamp(right_share, 0.0, 0.9);
  const double free_aspect = aspect * (1 - share);
  if (free_aspect < 1) c.distance /= float(std::max(free_aspect, 0.1));
  c.screen_shift_x = float(-share);
  // Look from the side the surface faces (its mean normal), turned a little for a 3/4 view;
  // surfaces that face every way (a vase) get the default view.
  if (glm::length(normal_sum) > 0.3 * area) {
    const glm::dvec3 n = glm::normalize(normal_sum);
    c.pitch = float(std::clamp(std::asin(n.z) * 0.8, -1.2, 1.2));
    // Facing up: look from the -y side so x runs across the image, as a plan is read.
    c.yaw = std::abs(n.z) > 0.9 ? -1.3f : float(std::atan2(n.y, n.x)) + 0.35f;
  }
  return c;
}

glm::mat4 MapView::projection(float aspect) const {
  const glm::mat4 framed = glm::ortho(-half_height * aspect, half_height * aspect, -half_height, half_height, -1.0f, 1.0f);
  return glm::translate(glm::rotate(framed, turn, glm::vec3(0, 0, 1)), glm::vec3(-centre, 0));
}

namespace {
glm::dvec2 turned(glm::dvec2 q, double turn) {
  const double c = std::cos(turn), s = std::sin(turn);
  return {c * q.x - s * q.y, s * q.x + c * q.y};
}
}  // namespace

glm::dvec2 MapView::screen_offset(glm::dvec2 q) const { return turned(q - glm::dvec2(centre), turn); }
glm::dvec2 MapView::map_point(glm::dvec2 offset) const { return glm::dvec2(centre) + turned(offset, -turn); }

MapView frame_map(const SurfaceMap& map, double aspect, double right_share, double left_share, double turn) {
  MapView v;
  v.turn = float(turn);
  // The map's box as the screen sees it (turned); a wrapping map frames its one period.
  glm::dvec2 lo = turned(map.uv_min, turn), hi = lo;
  if (turn != 0 && map.period <= 0) {
    for (const glm::dvec2& q : map.uv) lo = glm::min(lo, turned(q, turn)), hi = glm::max(hi, turned(q, turn));
  } else {
    for (const glm::dvec2 corner : {glm::dvec2(map.uv_max.x, map.uv_min.y), map.uv_max, glm::dvec2(map.uv_min.x, map.uv_max.y)})
      lo = glm::min(lo, turned(corner, turn)), hi = glm::max(hi, turned(corner, turn));
  }
  const glm::dvec2 extent = hi - lo;
  right_share = std::clamp(right_share, 0.0, 0.9);
  left_share = std::clamp(left_share, 0.0, 0.9 - right_share);
  // Fit both sides with a margin in the free part of the width; render_2d widens by the aspect.
  const double free_aspect = std::max(aspect * (1 - right_share - left_share), 1e-3);
  v.half_height = float(0.55 * std::max(extent.y, extent.x / free_aspect));
  // The free part's middle lies (right_share - left_share) of the half width off the view's centre.
  glm::dvec2 centre = 0.5 * (lo + hi);
  centre.x += (right_share - left_share) * v.half_height * aspect;
  v.centre = glm::vec2(turned(centre, -turn));
  return v;
}

double map_turn_to_match(const SurfaceMap& map, const OrbitCamera& camera, double aspect) {
  if (!map.chart_of_face.empty() || map.uv.size() != map.mesh.positions.size()) return 0;
  const glm::dmat4 vp = glm::dmat4(camera.view_projection(float(aspect)));
  // Screen points with x widened by the aspect, so that directions on screen keep their angles.
  std::vector<glm::dvec2> screen(map.uv.size());
  std::vector<bool> in_front(map.uv.size());
  for (std::size_t i = 0; i < screen.size(); ++i) {
    const glm::dvec4 clip = vp * glm::dvec4(map.mesh.positions[i], 1);
    in_front[i] = clip.w > 1e-9;
    if (in_front[i]) screen[i] = glm::dvec2(clip.x / clip.w * aspect, clip.y / clip.w);
  }
  // sum |e_uv| |e_screen| (sin, cos) of the angle between the two images of each edge: the angle
  // of that sum is the turn that takes the map's edges best onto the screen's.
  double front_sin = 0, front_cos = 0, all_sin = 0, all_cos = 0, front_weight = 0, all_weight = 0;
  const std::size_t stride = std::max<std::size_t>(1, map.mesh.triangles.size() / 20000);
  for (std::size_t t = 0; t < map.mesh.triangles.size(); t += stride) {
    const glm::ivec3 tri = map.mesh.triangles[t];
    if (!in_front[tri.x] || !in_front[tri.y] || !in_front[tri.z]) continue;
    double sin_sum = 0, cos_sum = 0;
    for (const auto& [a, b] : {std::pair{tri.x, tri.y}, std::pair{tri.x, tri.z}}) {
      glm::dvec2 along_map = map.uv[b] - map.uv[a];
      if (map.period > 0) along_map.x -= map.period * std::round(along_map.x / map.period);
      const glm::dvec2 along_screen = screen[b] - screen[a];
      sin_sum += along_map.x * along_screen.y - along_map.y * along_screen.x;
      cos_sum += glm::dot(along_map, along_screen);
    }
    const glm::dvec2 e1 = screen[tri.y] - screen[tri.x], e2 = screen[tri.z] - screen[tri.x];
    const double facing = e1.x * e2.y - e1.y * e2.x;  // counter-clockwise on screen: facing the camera
    const double weight = std::hypot(sin_sum, cos_sum);
    all_sin += sin_sum, all_cos += cos_sum, all_weight += weight;
    if (facing > 0) front_sin += sin_sum, front_cos += cos_sum, front_weight += weight;
  }
  // Seen mostly from behind (few triangles face the camera), every triangle counts.
  const bool front = front_weight > 0.2 * all_weight;
  const double s = front ? front_sin : all_sin, c = front ? front_cos : all_cos;
  if (std::hypot(s, c) <= 1e-12 * std::max(all_weight, 1e-300)) return 0;
  if (map.period > 0) return c >= 0 ? 0 : glm::pi<double>();
  return std::atan2(s, c);
}

std::vector<double> ratio_legend_ticks() { return {0.9, 1.0, 1.1, 1.2, 1.3}; }

std::array<std::uint8_t, 3> ratio_legend_colour(double ratio) { return neighbor_ratio_colours({ratio})[0]; }

double ratio_legend_position(double ratio) {
  return std::clamp((ratio - kRatioLegendMin) / (kRatioLegendMax - kRatioLegendMin), 0.0, 1.0);
}

std::vector<TypeLegendEntry> element_type_legend() {
  return {{"vertex element (V)", kind_colour(ElementKind::Vertex)},
          {"edge element (E)", kind_colour(ElementKind::Edge)},
          {"face element (F)", kind_colour(ElementKind::Face)},
          {"bead", kind_colour(ElementKind::Bead)}};
}

std::vector<std::array<std::uint8_t, 3>> element_colours(const Elements& elements, ColourMode mode, double gap) {
  if (mode == ColourMode::NeighbourRatio) return contact_colours(elements, gap);
  std::vector<std::array<std::uint8_t, 3>> out(elements.size());
  for (size_t i = 0; i < elements.size(); ++i)
    out[i] = kind_colour(elements.kind[i]);
  return out;
}

Renderer::Renderer() : impl_(std::make_unique<Impl>()) {}
Renderer::~Renderer() {
  if (impl_ && impl_->vk && impl_->vk->device) impl_->vk->device->waitIdle();
}

gpu::Result<std::unique_ptr<Renderer>> Renderer::create(std::shared_ptr<gpu::VulkanContext> context) {
  std::unique_ptr<Renderer> r(new Renderer());
  r->impl_->context = std::move(context);
  r->impl_->vk = &r->impl_->context->impl();
  try {
    r->impl_->create();
  } catch (const std::exception& e) {
    return gpu::vulkan_error("creating the renderer", e);
  }
  return r;
}

void Renderer::set_surface(const SurfaceMap& map) {
  Impl& d = *impl_;
  d.unfinished = {};  // drawn from the buffers about to be replaced
  std::vector<SurfaceVertex> vertices;
  for (int v = 0; v < map.mesh.vertex_count(); ++v)
    vertices.push_back({glm::vec3(map.mesh.positions[v]), glm::vec3(map.normals[v])});
  std::vector<std::uint32_t> indices;
  for (const auto& t : map.mesh.triangles) indices.insert(indices.end(), {std::uint32_t(t.x), std::uint32_t(t.y), std::uint32_t(t.z)});
  d.surface_vertices = d.host_buffer(vertices, vk::BufferUsageFlagBits::eVertexBuffer);
  d.surface_indices = d.host_buffer(indices, vk::BufferUsageFlagBits::eIndexBuffer);
  d.surface_index_count = std::uint32_t(indices.size());

  // The map: filled triangles, a light wireframe and the boundary in a darker line. A map that
  // wraps (a band's seamless map) is drawn with its neighbouring periods, faded.
  std::vector<FlatVertex> tris, lines;
  const std::uint32_t fill = pack_colour({206, 209, 214}), faded = pack_colour({112, 115, 121}), wire = pack_colour({170, 174, 182}),
                      edge = pack_colour({60, 64, 72});
  const std::vector<double> shifts = map_wraps(map) ? std::vector<double>{0.0, -map.period, map.period}
                                                    : std::vector<double>{0.0};
  const auto at = [](glm::dvec2 q, double shift) { return glm::vec3(float(q.x + shift), float(q.y), 0.0f); };
  for (const double shift : shifts)
    for (int f = 0; f < map.mesh.face_count(); ++f) {
      const std::array<glm::dvec2, 3> corner = triangle_uv(map, f);
      for (const glm::dvec2& q : corner) tris.push_back({at(q, shift), shift == 0 ? fill : faded});
      if (shift != 0) continue;
      const glm::ivec3 t = map.mesh.triangles[f];
      for (int k = 0; k < 3; ++k)
        if (t[k] < t[(k + 1) % 3]) {  // each interior edge once (it appears as a < b in one of its triangles)
          lines.push_back({at(corner[k], 0), wire});
          lines.push_back({at(corner[(k + 1) % 3], 0), wire});
        }
    }
  for (const double shift : shifts)
    for (const glm::ivec2& segment : boundary_segments(map.mesh)) {
      const glm::dvec2 a = map.uv[segment.x], b = nearest_image(map, map.uv[segment.y], a);
      lines.push_back({at(a, shift), edge});
      lines.push_back({at(b, shift), edge});
    }
  d.map_triangles = d.host_buffer(tris, vk::BufferUsageFlagBits::eVertexBuffer);
  d.map_lines = d.host_buffer(lines, vk::BufferUsageFlagBits::eVertexBuffer);
  d.map_triangle_count = std::uint32_t(tris.size());
  d.map_line_count = std::uint32_t(lines.size());
  d.lattice3d_count = d.lattice2d_count = d.disk_count = 0;
  d.instance_range.clear();
}

// Thousands of elements are drawn with coarser shapes, from 8,000 with minimal ones: at those
// counts each is a few pixels wide, and the triangle count would otherwise run into the millions.
// A software renderer's time goes with the triangles (paver-render-bench, docs/benchmarks.md):
// these thresholds keep every count up to about 50k elements within about 600k triangles.
ShapeDetail shape_detail_for(std::size_t element_count) {
  return element_count > kMinimalShapesAbove ? ShapeDetail::Minimal
         : element_count > kCoarseShapesAbove ? ShapeDetail::Coarse
                                              : ShapeDetail::Full;
}

void Renderer::set_elements(const Elements& elements, const std::vector<std::array<std::uint8_t, 3>>& colours,
                            const ShapeMesh* custom) {
  set_elements(prepare_elements(elements, colours, custom));
}

void Renderer::set_elements(const PreparedElements& prepared) {
  Impl& d = *impl_;
  d.unfinished = {};  // drawn from the buffers about to be replaced
  d.shape_vertices = d.host_buffer(prepared.shape_vertices, vk::BufferUsageFlagBits::eVertexBuffer);
  d.shape_range = prepared.shape_range;
  d.instances = d.host_buffer(prepared.instances, vk::BufferUsageFlagBits::eVertexBuffer);
  d.instance_range = prepared.instance_range;
  d.disks = d.host_buffer(prepared.disks, vk::BufferUsageFlagBits::eVertexBuffer);
  d.disk_count = std::uint32_t(prepared.disks.size());
}

void Renderer::set_pattern(const SurfaceMap& map, const Pattern& pattern, const std::vector<glm::dvec2>& points) {
  set_pattern(prepare_pattern(map, pattern, points));
}

void Renderer::set_pattern(const PreparedPattern& prepared) {
  Impl& d = *impl_;
  d.unfinished = {};  // drawn from the buffers about to be replaced
  d.lattice2d = d.host_buffer(prepared.lines2d, vk::BufferUsageFlagBits::eVertexBuffer);
  d.lattice3d = d.host_buffer(prepared.lines3d, vk::BufferUsageFlagBits::eVertexBuffer);
  d.lattice2d_count = std::uint32_t(prepared.lines2d.size());
  d.lattice3d_count = std::uint32_t(prepared.lines3d.size());
}

void Renderer::render(int view, const ViewRequest& request) {
  Impl& d = *impl_;
  d.unfinished[view].reset();
  RenderTarget& t = d.targets[view][d.shown[view]];
  if (t.ensure(*d.vk, *d.pass, request.width, request.height) || d.quick_shown[view]) ++d.image_changes[view];
  d.quick_shown[view] = false;
  ViewDrawing drawing = d.drawing_of(view, t, request);
  d.draw_slices(t, drawing, kWholeImage);
}

void Renderer::render_quick(int view, const ViewRequest& request) {
  Impl& d = *impl_;
  RenderTarget& t = d.targets[view][2];
  t.ensure(*d.vk, *d.pass, (request.width + 1) / 2, (request.height + 1) / 2);
  ViewRequest quick = request;
  quick.style.show_elements = quick.style.show_lattice = false;
  ViewDrawing drawing = d.drawing_of(view, t, quick);
  d.draw_slices(t, drawing, kWholeImage);
  d.quick_shown[view] = true;
  ++d.image_changes[view];
}

void Renderer::render_3d(int width, int height, const OrbitCamera& camera, const SceneStyle& style) {
  render(0, {width, height, camera, {}, style});
}

void Renderer::render_2d(int width, int height, const MapView& view, const SceneStyle& style) {
  render(1, {width, height, {}, view, style});
}

void Renderer::start_drawing(int view, const ViewRequest& request) {
  Impl& d = *impl_;
  RenderTarget& t = d.drawn_target(view);
  t.ensure(*d.vk, *d.pass, request.width, request.height);
  d.unfinished[view] = d.drawing_of(view, t, request);
}

bool Renderer::draw_more(int view, double budget_ms) {
  Impl& d = *impl_;
  if (!d.unfinished[view]) return false;
  if (!d.draw_slices(d.drawn_target(view), *d.unfinished[view], budget_ms)) return false;
  d.unfinished[view].reset();
  d.shown[view] = 1 - d.shown[view];
  d.quick_shown[view] = false;
  ++d.image_changes[view];
  return true;
}

bool Renderer::drawing(int view) const { return impl_->unfinished[view].has_value(); }

bool Renderer::drawing_begun(int view) const { return drawing(view) && impl_->unfinished[view]->cleared; }

void Renderer::stop_drawing(int view) { impl_->unfinished[view].reset(); }

Image Renderer::read_back(int view) {
  Impl& d = *impl_;
  RenderTarget& t = d.shown_target(view);
  Image out;
  out.width = t.width, out.height = t.height;
  out.rgba.resize(std::size_t(t.width) * t.height * 4);
  if (out.rgba.empty()) return out;
  gpu::GpuBuffer staging(*d.vk, out.rgba.size(), vk::BufferUsageFlagBits::eTransferDst,
                         vk::MemoryPropertyFlagBits::eHostVisible | vk::MemoryPropertyFlagBits::eHostCoherent,
                         vk::MemoryPropertyFlagBits::eHostCached);
  const vk::ImageSubresourceRange range(vk::ImageAspectFlagBits::eColor, 0, 1, 0, 1);
  d.vk->submit_and_wait([&](vk::raii::CommandBuffer& cb) {
    const vk::ImageMemoryBarrier to_copy(vk::AccessFlagBits::eColorAttachmentWrite, vk::AccessFlagBits::eTransferRead,
                                         vk::ImageLayout::eShaderReadOnlyOptimal, vk::ImageLayout::eTransferSrcOptimal,
                                         VK_QUEUE_FAMILY_IGNORED, VK_QUEUE_FAMILY_IGNORED, **t.colour.image, range);
    cb.pipelineBarrier(vk::PipelineStageFlagBits::eColorAttachmentOutput, vk::PipelineStageFlagBits::eTransfer, {}, {}, {},
                       to_copy);
    cb.copyImageToBuffer(**t.colour.image, vk::ImageLayout::eTransferSrcOptimal, staging.handle(),
                         vk::BufferImageCopy(0, 0, 0, vk::ImageSubresourceLayers(vk::ImageAspectFlagBits::eColor, 0, 0, 1),
                                             {0, 0, 0}, {std::uint32_t(t.width), std::uint32_t(t.height), 1}));
    const vk::ImageMemoryBarrier back(vk::AccessFlagBits::eTransferRead, vk::AccessFlagBits::eShaderRead,
                                      vk::ImageLayout::eTransferSrcOptimal, vk::ImageLayout::eShaderReadOnlyOptimal,
                                      VK_QUEUE_FAMILY_IGNORED, VK_QUEUE_FAMILY_IGNORED, **t.colour.image, range);
    const vk::BufferMemoryBarrier to_host(vk::AccessFlagBits::eTransferWrite, vk::AccessFlagBits::eHostRead,
                                          VK_QUEUE_FAMILY_IGNORED, VK_QUEUE_FAMILY_IGNORED, staging.handle(), 0, VK_WHOLE_SIZE);
    cb.pipelineBarrier(vk::PipelineStageFlagBits::eTransfer,
                       vk::PipelineStageFlagBits::eFragmentShader | vk::PipelineStageFlagBits::eHost, {}, {}, to_host, back);
  });
  std::memcpy(out.rgba.data(), staging.mapped(), out.rgba.size());
  return out;
}

void* Renderer::image_view(int view) const {
  const Impl& d = *impl_;
  const auto& t = d.targets[view][d.quick_shown[view] ? 2 : d.shown[view]];
  return t.colour.view ? reinterpret_cast<void*>(static_cast<VkImageView>(**t.colour.view)) : nullptr;
}
void* Renderer::sampler() const { return reinterpret_cast<void*>(static_cast<VkSampler>(**impl_->sampler)); }
int Renderer::image_generation(int view) const { return impl_->image_changes[view]; }

}  // namespace paver::render
