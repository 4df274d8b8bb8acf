#include "backend_choice.h"

#include "core/input_error.h"
#include "core/printable.h"

#include <cstdlib>

#ifdef PAVER_WITH_VULKAN
#include "paver/compute/vulkan_context.h"
#include "paver/compute/vulkan_spring_solver.h"
#endif

namespace paver::app {

BackendChoice choose_backend(const std::string& backend, const std::string& device, int threads) {
  if (backend != "cpu" && backend != "vulkan" && backend != "auto")
    throw InputError("backend '" + backend + "': use cpu, vulkan or auto");
  if (backend == "cpu" && !device.empty())
    throw InputError("--device " + printable(device) + " names a Vulkan device, but --backend cpu solves on the CPU; "
                     "drop --device, or use --backend vulkan");
  BackendChoice choice{cpu_solver_factory(threads), "cpu", ""};
  if (backend == "cpu") return choice;
  // A device the user named, by --device or $PAVER_VULKAN_DEVICE, must exist and is used, whatever
  // the backend: falling back silently would hide a typo.
  const char* from_environment = std::getenv("PAVER_VULKAN_DEVICE");
  const bool named = !device.empty() || (from_environment && *from_environment);
  const bool must_use_vulkan = backend == "vulkan" || named;
  const std::string flag = backend == "vulkan" ? "--backend vulkan" : !device.empty() ? "--device " + device : "--backend " + backend;
#ifdef PAVER_WITH_VULKAN
  gpu::ContextOptions options;
  options.device = device;
  auto context = gpu::VulkanContext::create(options);
  if (!context) {
    if (must_use_vulkan) throw InputError(flag + ": " + context.error().message);
    return choice;  // auto: no Vulkan, stay on the CPU
  }
  // auto takes a real GPU only: on a CPU implementation (lavapipe) the CPU solver is as fast.
  const std::string type = context.value()->device().type;
  if (backend == "auto" && !named && type != "discrete" && type != "integrated" && type != "virtual")
    return choice;
  auto session = gpu::VulkanSolverSession::create(context.value());
  if (!session) {
    if (must_use_vulkan) throw InputError(flag + ": " + session.error().message);
    return choice;
  }
  SolverFactory vulkan = gpu::vulkan_solver_factory(session.value());
  if (backend == "auto" && !named)
    return {routed_by_size(choice.factory, std::move(vulkan), kAutoGpuLeastParticles), "auto",
            context.value()->device().name};
  return {std::move(vulkan), "vulkan", context.value()->device().name};
#else
  if (must_use_vulkan) throw InputError(flag + ": this paver was built without Vulkan");
  return choice;
#endif
}

}  // namespace paver::app
