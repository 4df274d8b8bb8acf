#pragma once
// Frame times while a run is solving in the background: the UI must keep its pace meanwhile. A
// script session prints them when the run ends ("frames_while_solving"): the mean, the slowest
// frame, the 99th percentile, and the fewest frames drawn in any one second of the run (sliding),
// which is what "keeps 30 fps" means to the eye; and how many live images the views completed.
#include <string>
#include <vector>

namespace paver::studio {

struct SolvingFrames {
  std::vector<double> frame_ms;  // each frame's time, present to present
  int images_drawn_in_slices = 0;  // the views' live images completed (views_panel.cpp)
  bool solving = false;            // a run was solving at the last present
};

struct FramePace {
  int frames = 0;
  double mean_fps = 0, slowest_ms = 0, p99_ms = 0;
  int fewest_in_a_second = -1;  // -1: the run was shorter than a second
};

FramePace frame_pace(const std::vector<double>& frame_ms);
std::string describe(const FramePace& pace);

}  // namespace paver::studio
