// `paver keys`: every design.json key from the one table, as the Markdown table of
// docs/design_file.md (a test keeps that file equal to this output).
#include "commands.h"

#include "design/design_keys.h"

#include <iostream>

namespace paver::cli {

std::function<int()> add_keys_command(CLI::App& app) {
  app.add_subcommand("keys", "List every design.json key: type, default, range, unit, flag, meaning");
  return [] {
    std::cout << design_keys_markdown();
    return 0;
  };
}

}  // namespace paver::cli
