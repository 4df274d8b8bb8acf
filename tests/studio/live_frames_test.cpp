#include "live_frames.h"

#include "surface_maps.h"

#include "pipeline/pavement.h"

#include <gtest/gtest.h>

#include <chrono>
#include <functional>
#include <memory>
#include <thread>

namespace paver::studio {
namespace {

using namespace std::chrono_literals;

bool eventually(const std::function<bool()>& done) {
  for (auto start = std::chrono::steady_clock::now(); std::chrono::steady_clock::now() - start < 60s;) {
    if (done()) return true;
    std::this_thread::sleep_for(2ms);
  }
  return false;
}

// A live snapshot as a run publishes it: the dome's pattern before the solver moved it.
LiveSnapshot dome_snapshot(const SurfaceMap& map) {
  Design design;
  design.pattern.spacing = 6;
  const Pavement p = make_pavement(map, design);
  LiveSnapshot snapshot;
  snapshot.revision = 4;
  snapshot.sequence = 9;
  snapshot.pattern = std::make_shared<const Pattern>(p.pattern);
  snapshot.design = p.design;
  snapshot.points = p.pattern.points;
  return snapshot;
}

TEST(LiveFrames, AFrameIsPreparedOffTheUiThreadAndTakenOnce) {
  const std::shared_ptr<const SurfaceMap> map = test::bundled_map("dome");
  const LiveSnapshot snapshot = dome_snapshot(*map);
  LiveFrames frames;
  EXPECT_FALSE(frames.busy());
  frames.prepare(snapshot, {map, nullptr, render::ColourMode::NeighbourRatio, true});
  ASSERT_TRUE(eventually([&] { return !frames.busy(); }));
  std::optional<LiveFrame> frame = frames.take();
  ASSERT_TRUE(frame);
  EXPECT_FALSE(frames.take()) << "a frame is taken once";
  EXPECT_EQ(frame->revision, 4u);
  EXPECT_EQ(frame->sequence, 9u);

  // What the UI thread would have drawn itself: the snapshot's elements placed on its points.
  const Design& design = snapshot.design;
  const PlacedElements placed =
      place_all_elements(map_for_topology(*map, frame->topology), *snapshot.pattern, snapshot.points, design.elements,
                         design.pattern.spacing, edge_anchor(design.pattern.topology), false);
  ASSERT_GT(placed.elements.size(), 100u);
  const render::PreparedElements expected = render::prepare_elements(
      placed.elements, render::element_colours(placed.elements, render::ColourMode::NeighbourRatio), nullptr);
  ASSERT_EQ(frame->elements.instances.size(), expected.instances.size());
  for (std::size_t i = 0; i < expected.instances.size(); ++i) {
    EXPECT_EQ(frame->elements.instances[i].centre, expected.instances[i].centre);
    EXPECT_EQ(frame->elements.instances[i].colour, expected.instances[i].colour);
  }
  ASSERT_TRUE(frame->pattern) << "asked with the pattern's lines";
  EXPECT_EQ(frame->pattern->lines2d.size(), 2 * std::size_t(snapshot.pattern->edge_count()));
}

TEST(LiveFrames, AResetFrameIsNeverTaken) {
  const std::shared_ptr<const SurfaceMap> map = test::bundled_map("dome");
  LiveFrames frames;
  frames.prepare(dome_snapshot(*map), {map, nullptr, render::ColourMode::ElementType, false});
  frames.reset();
  EXPECT_FALSE(frames.busy());
  std::this_thread::sleep_for(200ms);  // long enough for the job to have finished
  EXPECT_FALSE(frames.take());
}

}  // namespace
}  // namespace paver::studio
