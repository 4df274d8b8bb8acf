// `paver parameters` and `paver keys`: the solver parameters and every design.json key, each from
// its one table, as the Markdown tables of docs/parameters.md and docs/design_file.md (tests keep
// those files equal to this output).
#include "commands.h"

#include "design/design_keys.h"
#include "design/solver_parameters.h"

#include <iostream>
#include <string>

namespace paver::cli {
namespace {

std::function<int()> add_table_command(CLI::App& app, const char* name, const char* description,
                                       std::string (*table)()) {
  app.add_subcommand(name, description);
  return [table] {
    std::cout << table();
    return 0;
  };
}

}  // namespace

std::function<int()> add_parameters_command(CLI::App& app) {
  return add_table_command(app, "parameters", "List the solver parameters (section 5): key, flag, default, range, unit",
                           solver_parameters_markdown);
}

std::function<int()> add_keys_command(CLI::App& app) {
  return add_table_command(app, "keys", "List every design.json key: type, default, range, unit, flag, meaning",
                           design_keys_markdown);
}

}  // namespace paver::cli
