#pragma once
// A stage's wall time in milliseconds, the unit of every report's timings. Steady clock: a clock
// change while a long pavement runs cannot make a stage take negative time.
#include <chrono>

namespace paver {

class Stopwatch {
public:
  Stopwatch() : start_(std::chrono::steady_clock::now()) {}
  double milliseconds() const {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count();
  }

private:
  std::chrono::steady_clock::time_point start_;
};

}  // namespace paver
