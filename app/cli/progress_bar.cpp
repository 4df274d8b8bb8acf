#include "progress_bar.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <memory>

namespace paver::cli {
namespace {
bool drawn = false;
}

SolverObserver terminal_progress_bar(int iterations) {
  if (!isatty(fileno(stderr)) || iterations <= 0) return {};
  auto last = std::make_shared<std::chrono::steady_clock::time_point>();
  return [iterations, last](int iteration, const std::vector<glm::vec2>&) {
    // At most 20 redraws a second: the solver can run thousands of iterations a second.
    const auto now = std::chrono::steady_clock::now();
    if (iteration < iterations && now - *last < std::chrono::milliseconds(50)) return true;
    *last = now;
    constexpr int kWidth = 30;
    const int filled = iteration * kWidth / iterations;
    std::fprintf(stderr, "\roptimize [%.*s%.*s] %d/%d", filled, "##############################", kWidth - filled,
                 "..............................", iteration, iterations);
    std::fflush(stderr);
    drawn = true;
    return true;
  };
}

void finish_progress_bar() {
  if (drawn) std::fprintf(stderr, "\r\033[K");
  drawn = false;
}

}  // namespace paver::cli
