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
  // Presents at t[0] = 0 (the one before the first frame) and t[i] = the end of frame i; the
  // window (t[i], t[i] + 1 s] holds the frames that end within a second after present i.
  // Windows that reach past the last present are not whole seconds: left out.
  std::vector<double> t(frame_ms.size() + 1, 0.0);
  std::partial_sum(frame_ms.begin(), frame_ms.end(), t.begin() + 1);
  std::size_t last_in = 0;
  for (std::size_t i = 0; i < t.size() && t[i] + 1000.0 <= t.back(); ++i) {
    last_in = std::max(last_in, i);
    while (last_in + 1 < t.size() && t[last_in + 1] <= t[i] + 1000.0) ++last_in;
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
