#pragma once
// The `paver` subcommands. Each registers its options on the CLI11 app and runs when chosen.
#include <CLI/CLI.hpp>

#include <functional>

namespace paver::cli {

// Returns the function that runs the command once the arguments are parsed; it returns the
// process exit code.
std::function<int()> add_param_command(CLI::App& app);
std::function<int()> add_run_command(CLI::App& app);
std::function<int()> add_devices_command(CLI::App& app);
std::function<int()> add_parameters_command(CLI::App& app);
std::function<int()> add_keys_command(CLI::App& app);

}  // namespace paver::cli
