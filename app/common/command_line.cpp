#include "command_line.h"

#include "core/closest_name.h"
#include "core/printable.h"

#include <cstdio>
#include <sstream>

namespace paver::app {

namespace {

// Every option that takes a value refuses an empty one, checked before its own checks: CLI11
// takes `--stone ""` for a number not given, and the run went on with spheres. A flag refuses a
// value: CLI11 took `--fit-offset=2` for "on", as if it counted something.
void refuse_meaningless_values(CLI::App& app) {
  for (CLI::Option* option : app.get_options()) {
    if (option->get_type_size_min() > 0) option->transform(not_empty());
    if (option->get_expected_max() == 0) option->disable_flag_override();
  }
  for (CLI::App* command : app.get_subcommands({})) refuse_meaningless_values(*command);
}

}  // namespace

std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv, const std::string& usage) {
  refuse_meaningless_values(app);
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
    // CLI11: "png was given a disallowed flag override".
    const std::size_t overridden = what.find(" was given a disallowed flag override");
    if (overridden != std::string::npos) {
      const std::string flag = what.substr(0, overridden);
      // A `--no-X` twin turns its key off (KeyFlag.bool_flag, app/cli/run_command.cpp).
      what = "--" + flag + " takes no value: give it alone to turn it " + (flag.rfind("no-", 0) == 0 ? "off" : "on");
    }
    // An unexpected flag that is a near miss of a real one: name the real one.
    // CLI11: "The following argument(s) were not expected: 3 --lambdar".
    const std::size_t listed = what.find("not expected: ");
    if (listed != std::string::npos) {
      std::vector<std::string> flags;
      for (const CLI::App* command : app.get_subcommands())  // the one that was parsed
        for (const CLI::Option* option : command->get_options())
          for (const std::string& name : option->get_lnames()) flags.push_back("--" + name);
      std::istringstream words(what.substr(listed + 14));
      for (std::string word; words >> word;)
        if (word.rfind("--", 0) == 0)
          if (const std::optional<std::string> best = closest_name(word, flags)) {
            what += " (did you mean " + *best + "?)";
            break;
          }
    }
    std::fprintf(stderr, "%s: error: %s (usage: %s; see --help)\n", app.get_name().c_str(),
                 paver::printable(what).c_str(), usage.c_str());
    return 2;
  }
  return std::nullopt;
}

const CLI::Validator& not_empty() {
  static const CLI::Validator validator(
      [](const std::string& value) {
        // "--design --quiet" took the flag for the design's file name ("--quiet: no such design file").
        if (value.rfind("--", 0) == 0) return "is missing its value (" + value + " is an option, not a value)";
        return value.empty() ? std::string("must not be empty") : std::string();
      },
      "",
      "NOT_EMPTY");
  return validator;
}

CLI::Option* add_backend_option(CLI::App& app, std::string& backend) {
  return app.add_option("--backend", backend, "Solver backend: cpu, vulkan, or auto (Vulkan on a GPU, else CPU)")
      ->check(CLI::IsMember({"cpu", "vulkan", "auto"}))
      ->capture_default_str();
}

}  // namespace paver::app
