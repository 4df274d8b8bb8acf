#include "command_line.h"

namespace paver::app {

std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  return std::nullopt;
}

CLI::Option* add_backend_option(CLI::App& app, std::string& backend) {
  return app.add_option("--backend", backend, "Solver backend: cpu, vulkan, or auto (Vulkan on a GPU, else CPU)")
      ->check(CLI::IsMember({"cpu", "vulkan", "auto"}))
      ->capture_default_str();
}

}  // namespace paver::app
