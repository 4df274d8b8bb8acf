#include "interrupt.h"

#include <csignal>

namespace paver::cli {
namespace {

std::atomic<bool> requested{false};
static_assert(std::atomic<bool>::is_always_lock_free, "the flag is set from a signal handler");

extern "C" void on_interrupt(int signal) {
  requested.store(true);
  std::signal(signal, SIG_DFL);  // a second one is not waited on
}

}  // namespace

void install_interrupt_handlers() {
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
}

const std::atomic<bool>& interrupt_requested() { return requested; }

}  // namespace paver::cli
