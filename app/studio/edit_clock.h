#pragma once
// The time from a design change to its result on screen, as the status line reports it: the time
// a run sat paused (Space, or a Step waiting for the next) is left out, so "N ms from the edit" is
// the studio's time, not the designer's coffee break.
#include <chrono>
#include <optional>

namespace paver::studio {

class EditClock {
public:
  using Clock = std::chrono::steady_clock;

  // A change (or a run started again): counting starts now, nothing paused yet.
  void restart(Clock::time_point now) {
    started_ = now;
    paused_ = Clock::duration::zero();
    paused_since_.reset();
  }
  void pause(Clock::time_point now) {
    if (!paused_since_) paused_since_ = now;
  }
  void resume(Clock::time_point now) {
    if (!paused_since_) return;
    paused_ += now - *paused_since_;
    paused_since_.reset();
  }
  // Milliseconds since the restart, less the paused time (a pause still open counts up to now).
  double ms(Clock::time_point now) const {
    const Clock::duration open = paused_since_ ? now - *paused_since_ : Clock::duration::zero();
    return std::chrono::duration<double, std::milli>(now - started_ - paused_ - open).count();
  }
  double paused_ms(Clock::time_point now) const {
    const Clock::duration open = paused_since_ ? now - *paused_since_ : Clock::duration::zero();
    return std::chrono::duration<double, std::milli>(paused_ + open).count();
  }

private:
  Clock::time_point started_ = Clock::now();
  Clock::duration paused_ = Clock::duration::zero();
  std::optional<Clock::time_point> paused_since_;
};

}  // namespace paver::studio
