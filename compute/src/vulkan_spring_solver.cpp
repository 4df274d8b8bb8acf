#include "paver/compute/vulkan_spring_solver.h"
#include "design/design_keys.h"

#include "core/stopwatch.h"
#include "paver/compute/gpu_buffer.h"
#include "solver/spring_solver.h"
#include "paver/compute/vulkan_objects.h"

#include <cstdint>
// SPIR-V embedded at build time by glslangValidator --vn (compute/CMakeLists.txt).
#include "solver_finish_comp_spv.h"
#include "solver_lift_comp_spv.h"
#include "solver_move_comp_spv.h"
#include "solver_springs_comp_spv.h"

#include <array>
#include <mutex>
#include <cstring>
#include <span>
#include <utility>

namespace paver::gpu {
namespace {


std::uint32_t groups(int items) { return std::uint32_t((items + int(kSolverGroupSize) - 1) / int(kSolverGroupSize)); }

template <class T>
std::size_t bytes_of(const std::vector<T>& v) {
  return v.size() * sizeof(T);
}


}  // namespace

struct VulkanSolverSession::Impl {
  std::shared_ptr<VulkanContext> context;
  VulkanContext::Impl* ctx = nullptr;
  std::optional<vk::raii::DescriptorSetLayout> set_layout;
  std::optional<vk::raii::PipelineLayout> pipeline_layout;
  std::optional<vk::raii::Pipeline> lift, springs, move, finish;
  std::optional<vk::raii::DescriptorPool> pool;
  std::vector<vk::raii::DescriptorSet> sets;  // [0]: positions A -> B, [1]: B -> A
  std::array<GpuBuffer, kBindingCount> buffers;
  GpuBuffer second_positions;
  GpuBuffer params;
  std::optional<StagingArena> staged_uploads, staged_downloads;
  std::uint64_t surface_key = 0;
  // One solve at a time: solvers made by one factory share these buffers and descriptor sets,
  // and the studio may start a new run before an abandoned one has finished its batch.
  std::mutex busy;
  int surface_uploads = 0;
  bool descriptors_dirty = true;

  vk::raii::Pipeline make_pipeline(std::span<const std::uint32_t> spirv) {
    vk::raii::ShaderModule module(*ctx->device, vk::ShaderModuleCreateInfo({}, spirv.size_bytes(), spirv.data()));
    vk::PipelineShaderStageCreateInfo stage({}, vk::ShaderStageFlagBits::eCompute, *module, "main");
    return vk::raii::Pipeline(*ctx->device, nullptr, vk::ComputePipelineCreateInfo({}, stage, **pipeline_layout));
  }

  void create() {
    std::vector<vk::DescriptorSetLayoutBinding> bindings;
    for (std::uint32_t b = 0; b < kBindingCount; ++b)
      bindings.emplace_back(b, b == kBindingParams ? vk::DescriptorType::eUniformBuffer : vk::DescriptorType::eStorageBuffer, 1,
                            vk::ShaderStageFlagBits::eCompute);
    set_layout.emplace(*ctx->device, vk::DescriptorSetLayoutCreateInfo({}, bindings));
    const vk::PushConstantRange push(vk::ShaderStageFlagBits::eCompute, 0, sizeof(SolverPush));
    const vk::DescriptorSetLayout raw_layout = **set_layout;
    pipeline_layout.emplace(*ctx->device, vk::PipelineLayoutCreateInfo({}, raw_layout, push));
    lift.emplace(make_pipeline(solver_lift_comp_spv));
    springs.emplace(make_pipeline(solver_springs_comp_spv));
    move.emplace(make_pipeline(solver_move_comp_spv));
    finish.emplace(make_pipeline(solver_finish_comp_spv));
    const vk::DescriptorPoolSize sizes[] = {{vk::DescriptorType::eUniformBuffer, 2},
                                            {vk::DescriptorType::eStorageBuffer, 2 * (kBindingCount - 1)}};
    pool.emplace(*ctx->device,
                 vk::DescriptorPoolCreateInfo(vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet, 2, sizes));
    const vk::DescriptorSetLayout layouts[] = {raw_layout, raw_layout};
    sets = vk::raii::DescriptorSets(*ctx->device, vk::DescriptorSetAllocateInfo(**pool, layouts));
    staged_uploads.emplace(*ctx, vk::BufferUsageFlagBits::eTransferSrc);
    staged_downloads.emplace(*ctx, vk::BufferUsageFlagBits::eTransferDst);
    params = GpuBuffer(*ctx, sizeof(SolverConstants), vk::BufferUsageFlagBits::eUniformBuffer,
                       vk::MemoryPropertyFlagBits::eHostVisible | vk::MemoryPropertyFlagBits::eHostCoherent, {});
  }

  // Makes binding `b` at least `bytes` large; returns true when it had to be reallocated.
  bool reserve(std::uint32_t b, std::size_t bytes) {
    GpuBuffer& buffer = b == kBindingPositionOut ? second_positions : buffers[b];
    if (buffer.valid() && buffer.size() >= bytes) return false;
    // Grow by half again so systems that gain a few contact springs keep their allocation.
    buffer = GpuBuffer(*ctx, std::max<std::size_t>(bytes + bytes / 2, 64),
                       vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eTransferDst |
                           vk::BufferUsageFlagBits::eTransferSrc);
    descriptors_dirty = true;
    return true;
  }

  void write_descriptors() {
    if (!descriptors_dirty) return;
    std::vector<vk::DescriptorBufferInfo> infos(2 * kBindingCount);
    std::vector<vk::WriteDescriptorSet> writes;
    for (int set = 0; set < 2; ++set)
      for (std::uint32_t b = 0; b < kBindingCount; ++b) {
        vk::Buffer buffer = b == kBindingParams ? params.handle() : buffers[b].handle();
        if (b == kBindingPositionIn) buffer = set == 0 ? buffers[kBindingPositionIn].handle() : second_positions.handle();
        if (b == kBindingPositionOut) buffer = set == 0 ? second_positions.handle() : buffers[kBindingPositionIn].handle();
        infos[set * kBindingCount + b] = vk::DescriptorBufferInfo(buffer, 0, VK_WHOLE_SIZE);
        writes.emplace_back(*sets[set], b, 0, 1,
                            b == kBindingParams ? vk::DescriptorType::eUniformBuffer : vk::DescriptorType::eStorageBuffer,
                            nullptr, &infos[set * kBindingCount + b]);
      }
    ctx->device->updateDescriptorSets(writes, {});
    descriptors_dirty = false;
  }
};

VulkanSolverSession::VulkanSolverSession() : impl_(std::make_unique<Impl>()) {}
VulkanSolverSession::~VulkanSolverSession() {
  if (impl_ && impl_->ctx && impl_->ctx->device) impl_->ctx->device->waitIdle();
}
VulkanContext& VulkanSolverSession::context() { return *impl_->context; }
int VulkanSolverSession::surface_uploads() const { return impl_->surface_uploads; }

Result<std::shared_ptr<VulkanSolverSession>> VulkanSolverSession::create(std::shared_ptr<VulkanContext> context) {
  std::shared_ptr<VulkanSolverSession> session(new VulkanSolverSession());
  session->impl_->context = std::move(context);
  session->impl_->ctx = &session->impl_->context->impl();
  try {
    session->impl_->create();
  } catch (const std::exception& e) {
    return vulkan_error("creating the solver's pipelines", e);
  }
  return session;
}

namespace {

class VulkanSpringSolver final : public SpringSolverBackend {
public:
  VulkanSpringSolver(std::shared_ptr<VulkanSolverSession> session, const SolverSurface& surface, SpringSystem& system,
                     const SolverParams& params, double spacing, int batch)
      : session_(std::move(session)), s_(session_->impl()), surface_(surface), system_(system), params_(params),
        threshold_(float(params.threshold * spacing)), batch_(std::max(1, batch)) {}

  std::string_view backend_name() const override { return "vulkan"; }

  SolveReport solve(const SolverObserver& observer, const std::atomic<bool>* stop) override {
    std::lock_guard lock(s_.busy);
    try {
      return run(observer, stop);
    } catch (const vk::SystemError& e) {
      throw std::runtime_error(vulkan_error("running the solver", e).message);
    }
  }

private:
  void upload_inputs(Transfers& t) {
    auto& d = s_;
    const std::uint64_t key = surface_.fingerprint;
    const SolverSurface& s = surface_;
    const SpringSystem& y = system_;
    pulled_.assign(y.particle_count(), 0u);
    struct Array {
      std::uint32_t binding;
      const void* data;
      std::size_t bytes;
    };
    auto array = [](std::uint32_t binding, const auto& v) { return Array{binding, v.data(), bytes_of(v)}; };
    const Array surface_arrays[] = {
        array(kBindingUv, s.uv), array(kBindingSurfacePosition, s.position), array(kBindingSurfaceCurvature, s.curvature),
        array(kBindingTriangles, s.triangles), array(kBindingGridStart, s.grid_start), array(kBindingGridTriangles, s.grid_triangles),
        array(kBindingBoundarySegments, s.boundary_segments), array(kBindingBoundaryInward, s.boundary_inward),
        array(kBindingBoundaryGridStart, s.boundary_grid_start), array(kBindingBoundaryGridSegments, s.boundary_grid_segments)};
    // The system changes between solves (a new design, contact springs): always uploaded.
    const Array system_arrays[] = {
        array(kBindingPositionIn, y.position), array(kBindingStrayCount, y.stray_count), array(kBindingTriangleHint, y.triangle_hint),
        array(kBindingPulledBack, pulled_), array(kBindingNeighborStart, y.neighbor_start), array(kBindingNeighbor, y.neighbor),
        array(kBindingNeighborSpring, y.neighbor_spring), array(kBindingSpringA, y.spring_a), array(kBindingSpringB, y.spring_b),
        array(kBindingRestLength, y.rest_length), array(kBindingSpringFlags, y.spring_flags), array(kBindingTarget, y.target),
        array(kBindingInitialTarget, y.initial_target)};
    bool surface_changed = key != d.surface_key;
    for (const Array& a : surface_arrays) surface_changed |= d.reserve(a.binding, a.bytes);
    if (surface_changed) {
      for (const Array& a : surface_arrays) t.upload(d.buffers[a.binding], a.data, a.bytes);
      // Known to be on the GPU only once the submission ran (submit): a solve that throws before
      // it leaves the next one to upload the surface again.
      d.surface_key = 0;
      uploading_surface_ = key;
      ++d.surface_uploads;
    }
    for (const Array& a : system_arrays) d.reserve(a.binding, a.bytes);
    d.reserve(kBindingPositionOut, bytes_of(y.position));
    d.reserve(kBindingLifted, std::size_t(y.particle_count()) * sizeof(glm::vec4));
    d.reserve(kBindingControl, kControlSlots * sizeof(std::uint32_t));
    for (const Array& a : system_arrays) t.upload(d.buffers[a.binding], a.data, a.bytes);
    control_.fill(0u);
    t.upload(d.buffers[kBindingControl], control_.data(), sizeof(control_));

    // Parameters: the same float32 constants the CPU kernels use.
    // The CPU kernels' constants, and what only the GPU needs.
    SolverConstants p = make_solver_constants(params_, s);
    p.threshold = threshold_;
    p.grid_cell_size = s.grid_cell_size;
    p.grid_origin = s.grid_origin;
    p.grid_nx = s.grid_nx, p.grid_ny = s.grid_ny, p.boundary_count = int(s.boundary_segments.size());
    p.particle_count = y.particle_count(), p.spring_count = y.spring_count();
    std::memcpy(d.params.mapped(), &p, sizeof p);
    d.write_descriptors();
  }

  void barrier(vk::raii::CommandBuffer& cb) {
    const vk::MemoryBarrier b(vk::AccessFlagBits::eShaderWrite, vk::AccessFlagBits::eShaderRead | vk::AccessFlagBits::eShaderWrite);
    cb.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader, vk::PipelineStageFlagBits::eComputeShader, {}, b, {}, {});
  }

  void dispatch(vk::raii::CommandBuffer& cb, const vk::raii::Pipeline& pipeline, int set, std::uint32_t count,
                SolverPush push = {}) {
    cb.bindPipeline(vk::PipelineBindPoint::eCompute, *pipeline);
    cb.bindDescriptorSets(vk::PipelineBindPoint::eCompute, **s_.pipeline_layout, 0, *s_.sets[set], {});
    cb.pushConstants<SolverPush>(**s_.pipeline_layout, vk::ShaderStageFlagBits::eCompute, 0, push);
    if (count > 0) cb.dispatch(count, 1, 1);
    barrier(cb);
  }

  // Iteration `it` (0-based, over the whole solve), on descriptor set it % 2.
  void record_iteration(vk::raii::CommandBuffer& cb, int it) {
    const int set = it % 2;
    const int n = system_.particle_count(), e = system_.spring_count();
    if (it > 0) {
      dispatch(cb, *s_.lift, set, groups(n), {1u, 0u});
      dispatch(cb, *s_.springs, set, groups(e), {0u, 0u});
    }
    dispatch(cb, *s_.move, set, groups(n));
    dispatch(cb, *s_.finish, set, 1);
  }

  // Records `body`, then the downloads, submits and waits, then copies the downloads out.
  void submit(Transfers& t, const std::function<void(vk::raii::CommandBuffer&)>& body) {
    s_.ctx->submit_and_wait([&](vk::raii::CommandBuffer& cb) {
      t.record_uploads(cb);
      // The previous submission's shader writes (an earlier batch) before this one's reads.
      barrier(cb);
      body(cb);
      t.record_downloads(cb);
    });
    t.finish();
    if (uploading_surface_ != 0) s_.surface_key = std::exchange(uploading_surface_, 0);
  }

  SolveReport run(const SolverObserver& observer, const std::atomic<bool>* stop) {
    const Stopwatch watch;
    const int n = system_.particle_count(), e = system_.spring_count();
    Transfers t(*s_.staged_uploads, *s_.staged_downloads);
    upload_inputs(t);
    // The initial lift and spring pass, like CpuSpringSolver's constructor.
    bool init_pending = true;
    int recorded = 0;
    SolveReport report;
    report.reason = StopReason::IterationLimit;
    std::vector<glm::vec2> observed;
    while (recorded < params_.iterations) {
      const int count = std::min(batch_, params_.iterations - recorded);
      if (observer) observed.resize(n);
      t.download(s_.buffers[kBindingControl], control_.data(), sizeof(control_));
      const int end = recorded + count;
      if (observer) t.download(end % 2 == 0 ? s_.buffers[kBindingPositionIn] : s_.second_positions, observed.data(), bytes_of(observed));
      submit(t, [&](vk::raii::CommandBuffer& cb) {
        if (init_pending) {
          dispatch(cb, *s_.lift, 0, groups(n), {1u, 1u});
          dispatch(cb, *s_.springs, 0, groups(e), {1u, 0u});
        }
        for (int it = recorded; it < end; ++it) record_iteration(cb, it);
      });
      init_pending = false;
      recorded = end;
      check_errors();
      // Observer first, then convergence: the order of CpuSpringSolver::solve.
      if ((observer && !observer(int(control_[kControlIterations]), observed)) || (stop && stop->load())) {
        report.reason = StopReason::Observer;
        break;
      }
      if (control_[kControlDone] != 0u) {
        report.reason = StopReason::Converged;
        break;
      }
    }
    // The closing lift (no stray counting), then read the state back into the system.
    const int final_set = recorded % 2;
    t.download(final_set == 0 ? s_.buffers[kBindingPositionIn] : s_.second_positions, system_.position.data(),
               bytes_of(system_.position));
    t.download(s_.buffers[kBindingStrayCount], system_.stray_count.data(), bytes_of(system_.stray_count));
    t.download(s_.buffers[kBindingTriangleHint], system_.triangle_hint.data(), bytes_of(system_.triangle_hint));
    t.download(s_.buffers[kBindingTarget], system_.target.data(), bytes_of(system_.target));
    t.download(s_.buffers[kBindingInitialTarget], system_.initial_target.data(), bytes_of(system_.initial_target));
    t.download(s_.buffers[kBindingControl], control_.data(), sizeof(control_));
    submit(t, [&](vk::raii::CommandBuffer& cb) {
      if (init_pending) {  // zero iterations asked for: still initialise like the CPU does
        dispatch(cb, *s_.lift, 0, groups(n), {1u, 1u});
        dispatch(cb, *s_.springs, 0, groups(e), {1u, 0u});
      }
      dispatch(cb, *s_.lift, final_set, groups(n), {0u, 1u});
    });
    check_errors();
    report.iterations = int(control_[kControlIterations]);
    std::memcpy(&report.last_max_step, &control_[kControlLastMaxStep], sizeof(float));
    report.strays_pulled_back = int(control_[kControlStrays]);
    report.milliseconds = watch.milliseconds();
    return report;
  }

  void check_errors() const {
    if (control_[kControlError] & kErrorNonFinite)
      throw std::runtime_error("vulkan solver: a particle has a non-finite position (the solver diverged; try a "
                               "smaller " + key_path(Key::solver_dt) + ")");
    if (control_[kControlError] & kErrorNotLifted)
      throw std::runtime_error("vulkan solver: a particle could not be lifted onto the map");
  }

  std::shared_ptr<VulkanSolverSession> session_;
  VulkanSolverSession::Impl& s_;
  const SolverSurface& surface_;
  SpringSystem& system_;
  SolverParams params_;
  float threshold_;
  int batch_;
  std::vector<std::uint32_t> pulled_;
  std::uint64_t uploading_surface_ = 0;  // the surface key of uploads not yet submitted
  std::array<std::uint32_t, kControlSlots> control_{};
};

}  // namespace

SolverFactory vulkan_solver_factory(std::shared_ptr<VulkanSolverSession> session, int batch) {
  return [session, batch](const SolverSurface& surface, SpringSystem& system, const SolverParams& params,
                          double spacing) -> std::unique_ptr<SpringSolverBackend> {
    return std::make_unique<VulkanSpringSolver>(session, surface, system, params, spacing, batch);
  };
}

}  // namespace paver::gpu
