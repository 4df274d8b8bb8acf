// `paver parameters`: the solver parameters from the one table, as the Markdown table of
// docs/parameters.md (a test keeps that file equal to this output).
#include "commands.h"

#include "design/solver_parameters.h"

#include <iostream>

namespace paver::cli {

std::function<int()> add_parameters_command(CLI::App& app) {
  app.add_subcommand("parameters", "List the solver parameters (section 5): key, flag, default, range, unit");
  return [] {
    std::cout << solver_parameters_markdown();
    return 0;
  };
}

}  // namespace paver::cli
