#include "command_line.h"

#include "core/printable.h"

#include <cstdio>

namespace paver::app {

std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv, const std::string& usage) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    std::fprintf(stderr, "%s: %s (usage: %s; see --help)\n", app.get_name().c_str(), paver::printable(e.what()).c_str(),
                 usage.c_str());
    return 2;
  }
  return std::nullopt;
}

CLI::Option* add_backend_option(CLI::App& app, std::string& backend) {
  return app.add_option("--backend", backend, "Solver backend: cpu, vulkan, or auto (Vulkan on a GPU, else CPU)")
      ->check(CLI::IsMember({"cpu", "vulkan", "auto"}))
      ->capture_default_str();
}

}  // namespace paver::app
