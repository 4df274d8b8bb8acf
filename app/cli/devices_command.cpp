// `paver devices`: the Vulkan devices found, and which one --backend vulkan would use.
#include "commands.h"

#include <cstdio>

#ifdef PAVER_WITH_VULKAN
#include "paver/compute/vulkan_context.h"
#endif

namespace paver::cli {

std::function<int()> add_devices_command(CLI::App& app) {
  app.add_subcommand("devices", "List the Vulkan devices and the one the Vulkan backend picks");
  return [] {
#ifdef PAVER_WITH_VULKAN
    const auto devices = gpu::list_devices();
    if (!devices) {
      std::printf("no Vulkan: %s\n", devices.error().message.c_str());
      return 1;
    }
    for (const auto& d : devices.value())
      std::printf("  %-40s %-10s Vulkan %s%s\n", d.name.c_str(), d.type.c_str(), d.api_version.c_str(),
                  d.compute ? "" : "  (not usable: needs a compute queue, Vulkan 1.2 and subgroup arithmetic)");
    const auto chosen = gpu::VulkanContext::create({});
    if (chosen) std::printf("--backend vulkan uses: %s\n", chosen.value()->device().name.c_str());
    else std::printf("--backend vulkan: %s\n", chosen.error().message.c_str());
    return chosen ? 0 : 1;
#else
    std::printf("this paver was built without Vulkan (PAVER_WITH_VULKAN=OFF)\n");
    return 1;
#endif
  };
}

}  // namespace paver::cli
