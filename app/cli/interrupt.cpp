#include "interrupt.h"

#include <signal.h>
#include <time.h>
#include <unistd.h>

namespace paver::cli {
namespace {

std::atomic<bool> requested{false};
std::atomic<int> first_signal{SIGINT};  // the exit code says which: 128 + signal (130 SIGINT, 143 SIGTERM)
// kWorking: the flag is polled; kNothingWritten: a request ends the process at once; kEnding: it is.
enum State : int { kWorking, kNothingWritten, kEnding };
std::atomic<int> state{kWorking};
std::atomic<long long> first_request_ns{0};
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<long long>::is_always_lock_free &&
                  std::atomic<int>::is_always_lock_free,
              "all are touched from a signal handler");

constexpr long long kForceAfterNs = 1'000'000'000;

long long monotonic_ns() {  // clock_gettime is async-signal-safe
  timespec now{};
  clock_gettime(CLOCK_MONOTONIC, &now);
  return static_cast<long long>(now.tv_sec) * 1'000'000'000 + now.tv_nsec;
}

extern "C" void on_interrupt(int signal_number) {
  if (!requested.load()) first_signal.store(signal_number);
  int expected = kNothingWritten;
  if (state.compare_exchange_strong(expected, kEnding)) {
    static const char message[] = "paver: interrupted; nothing was written\n";
    [[maybe_unused]] const auto written = write(STDERR_FILENO, message, sizeof message - 1);
    _exit(128 + first_signal.load());
  }
  const long long now = monotonic_ns();
  if (!requested.exchange(true)) {
    first_request_ns.store(now);
    return;
  }
  if (now - first_request_ns.load() < kForceAfterNs) return;
  static const char message[] = "paver: interrupted again; stopped at once\n";
  [[maybe_unused]] const auto written = write(STDERR_FILENO, message, sizeof message - 1);
  _exit(128 + first_signal.load());
}

}  // namespace

void install_interrupt_handlers() {
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  // Past a file size limit (ulimit -f) the write fails with EFBIG and is reported like a full disk,
  // the staging folder removed; by default the signal killed the run silently and left it behind.
  signal(SIGXFSZ, SIG_IGN);
  // A parent may have blocked them (signal masks are inherited); a blocked Ctrl-C would never arrive.
  sigset_t ours;
  sigemptyset(&ours);
  sigaddset(&ours, SIGINT);
  sigaddset(&ours, SIGTERM);
  sigprocmask(SIG_UNBLOCK, &ours, nullptr);
}

const std::atomic<bool>& interrupt_requested() { return requested; }

int interrupted_exit_code() { return 128 + first_signal.load(); }

void nothing_written_yet() {
  state = kNothingWritten;
  // A request that came before this call is honoured now, the same way.
  if (requested.load()) on_interrupt(first_signal.load());
}

void writing_starts() {
  int expected = kNothingWritten;
  if (state.compare_exchange_strong(expected, kWorking) || expected == kWorking) return;
  for (;;) pause();  // kEnding: the handler is ending the process on another thread
}

}  // namespace paver::cli
