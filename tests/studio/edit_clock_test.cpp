#include "edit_clock.h"

#include <gtest/gtest.h>

namespace paver::studio {
namespace {

using namespace std::chrono_literals;

TEST(EditClock, PausedTimeIsLeftOut) {
  const EditClock::Clock::time_point t0{};
  EditClock clock;
  clock.restart(t0);
  EXPECT_DOUBLE_EQ(clock.ms(t0 + 120ms), 120);
  clock.pause(t0 + 100ms);
  EXPECT_DOUBLE_EQ(clock.ms(t0 + 5s), 100) << "a pause still open stops the count";
  clock.pause(t0 + 6s);  // pausing twice is one pause
  clock.resume(t0 + 10100ms);
  EXPECT_DOUBLE_EQ(clock.ms(t0 + 10150ms), 150);
  EXPECT_DOUBLE_EQ(clock.paused_ms(t0 + 10150ms), 10000);
  clock.resume(t0 + 11s);  // resuming when running changes nothing
  EXPECT_DOUBLE_EQ(clock.ms(t0 + 10200ms), 200);
  clock.restart(t0 + 20s);
  EXPECT_DOUBLE_EQ(clock.ms(t0 + 20s + 30ms), 30) << "a new change counts from zero";
  EXPECT_DOUBLE_EQ(clock.paused_ms(t0 + 20s + 30ms), 0);
}

}  // namespace
}  // namespace paver::studio
