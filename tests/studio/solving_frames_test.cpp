#include "solving_frames.h"

#include <gtest/gtest.h>

#include <vector>

namespace paver::studio {
namespace {

TEST(FramePace, EvenFramesGiveTheirRateInEverySecond) {
  const std::vector<double> frames(300, 20.0);  // 6 s at 50 fps
  const FramePace pace = frame_pace(frames);
  EXPECT_EQ(pace.frames, 300);
  EXPECT_NEAR(pace.mean_fps, 50.0, 1e-9);
  EXPECT_DOUBLE_EQ(pace.slowest_ms, 20.0);
  EXPECT_DOUBLE_EQ(pace.p99_ms, 20.0);
  EXPECT_EQ(pace.fewest_in_a_second, 50);
}

TEST(FramePace, OneStallShowsInTheSecondThatHoldsIt) {
  // 50 fps, but one frame of 600 ms: the mean hides it, the worst second does not.
  std::vector<double> frames(400, 20.0);
  frames[200] = 600.0;
  const FramePace pace = frame_pace(frames);
  EXPECT_GT(pace.mean_fps, 40.0);
  EXPECT_DOUBLE_EQ(pace.slowest_ms, 600.0);
  // A second that holds the stall holds it and at most 400 ms of 20 ms frames.
  EXPECT_EQ(pace.fewest_in_a_second, 21);
}

TEST(FramePace, AStallAtTheStartCounts) {
  std::vector<double> frames(100, 20.0);
  frames[0] = 600.0;  // the first frame: the second from the run's start holds it and 20 more
  EXPECT_EQ(frame_pace(frames).fewest_in_a_second, 21);
  EXPECT_EQ(frame_pace(std::vector<double>(50, 20.0)).fewest_in_a_second, 50) << "exactly one second";
}

TEST(FramePace, ThePercentileIgnoresTheRareSlowFrame) {
  std::vector<double> frames(1000, 10.0);
  for (int i = 0; i < 5; ++i) frames[i * 200] = 50.0;  // 0.5% of the frames
  const FramePace pace = frame_pace(frames);
  EXPECT_DOUBLE_EQ(pace.p99_ms, 10.0);
  EXPECT_DOUBLE_EQ(pace.slowest_ms, 50.0);
}

TEST(FramePace, ARunShorterThanASecondHasNoWholeSecond) {
  const FramePace pace = frame_pace(std::vector<double>(10, 20.0));
  EXPECT_EQ(pace.fewest_in_a_second, -1);
  EXPECT_EQ(frame_pace({}).frames, 0);
}

}  // namespace
}  // namespace paver::studio
