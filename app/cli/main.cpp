// paver: the command-line driver of the Paver pipeline.
#include "command_line.h"
#include "commands.h"

#include "core/input_error.h"
#include "core/printable.h"
#include "core/interrupted.h"
#include "core/regular_file.h"
#include "available_memory.h"
#include "interrupt.h"

#include <CLI/CLI.hpp>

#include <cstdint>
#include <exception>
#include <new>
#include <iostream>

int main(int argc, char** argv) {
  paver::cli::install_interrupt_handlers();  // first: a Ctrl-C at any moment finds them in place
  CLI::App app{"Paver: element-based pattern creation on 3D free-form surfaces", "paver"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "paver 0.1.0");
  const auto run_param = paver::cli::add_param_command(app);
  const auto run_run = paver::cli::add_run_command(app);
  const auto run_devices = paver::cli::add_devices_command(app);
  const auto run_parameters = paver::cli::add_parameters_command(app);
  const auto run_keys = paver::cli::add_keys_command(app);
  if (const auto exit_code = paver::app::parse_command_line(app, argc, argv, "paver run|param|devices|parameters|keys ..."))
    return *exit_code;
  try {
    if (app.got_subcommand("param")) return run_param();
    if (app.got_subcommand("run")) return run_run();
    if (app.got_subcommand("devices")) return run_devices();
    if (app.got_subcommand("parameters")) return run_parameters();
    if (app.got_subcommand("keys")) return run_keys();
  } catch (const paver::Interrupted&) {
    std::cerr << "paver: interrupted; nothing was written, the output folder is as it was\n";
    return paver::cli::interrupted_exit_code();
  } catch (const paver::InputError& e) {
    std::cerr << "paver: error: " << paver::printable_cut(e.what(), paver::kMaxMessageBytes) << "\n";
    return 2;
  } catch (const std::bad_alloc&) {
    // An input too large for this machine is the input's problem, not ours: exit 2, with the figure.
    std::cerr << "paver: error: ran out of memory (" << paver::byte_size_text(std::uintmax_t(paver::app::available_memory_bytes()))
              << " was free when it stopped); simplify the surface or the design, or run on a machine with more memory\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "paver: internal error: " << paver::printable_cut(e.what(), paver::kMaxMessageBytes) << "\n";
    return 1;
  }
  return 2;
}
