#include "solving_frames.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

namespace paver::studio {

FramePace frame_pace(const std::vector<double>& frame_ms) {
  FramePace pace;
  pace.frames = int(frame_ms.size());
  if (frame_ms.empty()) return pace;
  const double total = std::accumulate(frame_ms.begin(), frame_ms.end(), 0.0);
  pace.mean_fps = total > 0 ? 1000.0 * pace.frames / total : 0;
  std::vector<double> sorted = frame_ms;
  std::sort(sorted.begin(), sorted.end());
  pace.slowest_ms = sorted.back();
  pace.p99_ms = sorted[std::min(sorted.size() - 1, std::size_t(std::ceil(0.99 * double(sorted.size()))) - 1)];
  // Frame i ends at end[i]; the window (end[i], end[i] + 1 s] holds the frames after it that end
  // within a second. Windows that reach past the last frame are not whole seconds: left out.
  std::vector<double> end(frame_ms.size());
  std::partial_sum(frame_ms.begin(), frame_ms.end(), end.begin());
  std::size_t last_in = 0;
  for (std::size_t i = 0; i < end.size() && end[i] + 1000.0 <= end.back(); ++i) {
    last_in = std::max(last_in, i);
    while (last_in + 1 < end.size() && end[last_in + 1] <= end[i] + 1000.0) ++last_in;
    const int in_window = int(last_in - i);
    pace.fewest_in_a_second = pace.fewest_in_a_second < 0 ? in_window : std::min(pace.fewest_in_a_second, in_window);
  }
  return pace;
}

std::string describe(const FramePace& pace) {
  char text[200];
  std::snprintf(text, sizeof text, "%d, %.1f fps mean, slowest %.1f ms, p99 %.1f ms, fewest in a second %d",
                pace.frames, pace.mean_fps, pace.slowest_ms, pace.p99_ms, pace.fewest_in_a_second);
  return text;
}

}  // namespace paver::studio
