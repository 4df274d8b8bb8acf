#include "command_line.h"

#include "core/printable.h"

#include <cstdio>

namespace paver::app {

std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv, const std::string& usage) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    // CLI11 says "A subcommand is required" for a misspelt one: name it instead.
    std::string what = e.what();
    if (argc > 1 && argv[1][0] != '-' && !app.get_subcommands({}).empty()) {
      bool known = false;
      for (const CLI::App* sub : app.get_subcommands({})) known = known || sub->get_name() == argv[1];
      if (!known) what = std::string("unknown command '") + argv[1] + "'";
    }
    std::fprintf(stderr, "%s: error: %s (usage: %s; see --help)\n", app.get_name().c_str(),
                 paver::printable(what).c_str(), usage.c_str());
    return 2;
  }
  return std::nullopt;
}

const CLI::Validator& not_empty() {
  static const CLI::Validator validator(
      [](const std::string& value) { return value.empty() ? std::string("must not be empty") : std::string(); }, "",
      "NOT_EMPTY");
  return validator;
}

CLI::Option* add_backend_option(CLI::App& app, std::string& backend) {
  return app.add_option("--backend", backend, "Solver backend: cpu, vulkan, or auto (Vulkan on a GPU, else CPU)")
      ->check(CLI::IsMember({"cpu", "vulkan", "auto"}))
      ->capture_default_str();
}

}  // namespace paver::app
