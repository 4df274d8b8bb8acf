#pragma once
// The live view's frames made ready off the UI thread. Placing a snapshot's elements on the
// surface (eq. 1), colouring them by their neighbours and building the renderer's instances took
// the UI thread 20-40 ms per snapshot at 46k elements on 2 cores: a frame of its own. Here a
// worker does it, and the UI thread only copies the result into the renderer's buffers.
// One frame is prepared at a time; the UI asks for the next when it has shown the last.
#include "background_jobs.h"
#include "live_pavement.h"

#include "renderer.h"
#include "scene_data.h"

#include <cstdint>
#include <memory>
#include <optional>

namespace paver::studio {

struct LiveFrame {
  std::uint64_t revision = 0, sequence = 0;  // the snapshot's
  Topology topology = Topology::Lattice;    // which map its points are on (map_for_topology)
  render::ColourMode colour_mode = render::ColourMode::NeighbourRatio;  // its elements' colouring
  render::PreparedElements elements;
  std::optional<render::PreparedPattern> pattern;  // when the pattern's lines are shown
};

struct LiveFrameRequest {
  std::shared_ptr<const SurfaceMap> map;
  std::shared_ptr<const ShapeMesh> custom_shape;
  render::ColourMode colour_mode = render::ColourMode::NeighbourRatio;
  bool with_pattern = false;
};

class LiveFrames {
public:
  bool busy() const;
  void prepare(LiveSnapshot snapshot, LiveFrameRequest request);
  std::optional<LiveFrame> take();  // the frame prepared, once
  void reset();                     // a frame being prepared is not wanted any more

private:
  struct Slot;
  std::shared_ptr<Slot> slot_;  // the frame being prepared; a new one after reset
  BackgroundJobs jobs_;
};

}  // namespace paver::studio
