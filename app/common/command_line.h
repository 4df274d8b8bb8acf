#pragma once
// Command-line pieces `paver` and `paver-studio` share, so both speak alike.
#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <string_view>

namespace paver::app {

// Parses argv; returns the exit code when the program should stop now: 0 after --help or
// --version, 2 for a bad argument, with one line on stderr: "PROGRAM: error: what is wrong (usage;
// see --help)". CLI11's own codes (106 ...) and its two-line message would tell a script nothing more.
std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv, const std::string& usage);

// Refuses an empty value (`--pattern ""` and `--stone ""` were taken as not given at all), and one
// that is an option ("--design --quiet" took the flag for a file). parse_command_line puts it on
// every option that takes a value.
const CLI::Validator& not_empty();

// --backend cpu|vulkan|auto (default auto), as choose_backend takes it.
CLI::Option* add_backend_option(CLI::App& app, std::string& backend);

}  // namespace paver::app
