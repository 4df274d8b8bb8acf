#include "progress.h"

#include "core/printable.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace paver::cli {
namespace {

using Clock = std::chrono::steady_clock;
constexpr auto kTerminalRedraw = std::chrono::milliseconds(50);
constexpr auto kLogDetail = std::chrono::seconds(2);

std::string words(std::string name) {
  std::replace(name.begin(), name.end(), '_', ' ');
  return name;
}

}  // namespace

bool stderr_is_terminal() { return isatty(STDERR_FILENO) != 0; }

Progress::Progress(bool quiet, bool terminal) : quiet_(quiet), terminal_(terminal) {}

Progress::~Progress() { finish(); }

void Progress::stage(const std::string& name) {
  if (quiet_ || name == stage_) return;
  stage_ = name;
  last_ = Clock::now();
  if (terminal_) {
    draw(0, "");
  } else {
    std::fprintf(stderr, "paver: %s\n", words(name).c_str());
    std::fflush(stderr);
  }
}

void Progress::fraction(double done, const std::string& detail) {
  if (quiet_) return;
  const auto now = Clock::now();
  if (now - last_ < (terminal_ ? Clock::duration(kTerminalRedraw) : Clock::duration(kLogDetail)) && done < 1) return;
  last_ = now;
  if (terminal_) {
    draw(done, detail);
  } else if (!detail.empty()) {
    std::fprintf(stderr, "paver: %s: %s\n", words(stage_).c_str(), printable(detail).c_str());
    std::fflush(stderr);
  }
}

void Progress::draw(double done, const std::string& detail) {
  constexpr int kWidth = 30;
  const int filled = std::clamp(int(done * kWidth), 0, kWidth);
  std::fprintf(stderr, "\r\033[K%-20s [%.*s%.*s] %s", words(stage_).c_str(), filled, "##############################",
               kWidth - filled, "..............................", printable(detail).c_str());
  std::fflush(stderr);
  drawn_ = true;
}

void Progress::finish() {
  if (drawn_) std::fprintf(stderr, "\r\033[K");
  std::fflush(stderr);
  drawn_ = false;
}

PipelineProgress Progress::mapping() {
  return [this](float done, const std::string& text) {
    const size_t colon = text.find(':');
    const std::string name = text.substr(0, colon);
    if (name == "mapped") return;
    stage(name);
    fraction(done, colon == std::string::npos ? "" : text.substr(std::min(colon + 2, text.size())));
  };
}

SolverObserver Progress::solver(int iterations) {
  if (quiet_ || iterations <= 0) return {};
  return [this, iterations](int iteration, const std::vector<glm::vec2>&) {
    fraction(double(iteration) / iterations, "iteration " + std::to_string(iteration) + " / " + std::to_string(iterations));
    return true;
  };
}

}  // namespace paver::cli
