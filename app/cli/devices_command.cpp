// `paver devices`: the Vulkan devices found, and which one --backend vulkan would use.
#include "commands.h"

#include "core/input_error.h"

#include <cstdio>

#ifdef PAVER_WITH_VULKAN
#include "paver/compute/vulkan_context.h"
#endif

namespace paver::cli {

std::function<int()> add_devices_command(CLI::App& app) {
  app.add_subcommand("devices", "List the Vulkan devices and the one the Vulkan backend picks");
  return []() -> int {
#ifdef PAVER_WITH_VULKAN
    // No Vulkan, or no device that $PAVER_VULKAN_DEVICE names: exit 2 with one line on stderr,
    // like any other input or set-up the user can fix (exit 1 is for Paver's own failures).
    const auto devices = gpu::list_devices();
    if (!devices) throw InputError("no Vulkan: " + devices.error().message);
    for (const auto& d : devices.value())
      std::printf("  %-40s %-10s Vulkan %s%s\n", d.name.c_str(), d.type.c_str(), d.api_version.c_str(),
                  d.compute ? "" : "  (not usable: needs a compute queue, Vulkan 1.2 and subgroup arithmetic)");
    const auto chosen = gpu::VulkanContext::create({});
    if (!chosen) throw InputError("--backend vulkan: " + chosen.error().message);
    std::printf("--backend vulkan uses: %s\n", chosen.value()->device().name.c_str());
    return 0;
#else
    throw InputError("this paver was built without Vulkan (PAVER_WITH_VULKAN=OFF); build it with Vulkan to list devices");
#endif
  };
}

}  // namespace paver::cli
