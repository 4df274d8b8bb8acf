#include "live_frames.h"

#include "pipeline/pavement.h"

#include <mutex>
#include <utility>

namespace paver::studio {

namespace {

std::optional<LiveFrame> prepare_frame(const LiveSnapshot& snapshot, const LiveFrameRequest& request,
                                       const std::stop_token& stop) {
  LiveFrame frame;
  frame.revision = snapshot.revision;
  frame.sequence = snapshot.sequence;
  frame.topology = snapshot.design.pattern.topology;
  frame.colour_mode = request.colour_mode;
  const SurfaceMap& map = map_for_topology(*request.map, frame.topology);
  // Post-processing is left out while the particles move: it is the slow part, and only the
  // final pavement is exported.
  const Design& design = snapshot.design;
  const PlacedElements placed = place_all_elements(map, *snapshot.pattern, snapshot.points, design.elements,
                                                   design.pattern.spacing, edge_anchor(design.pattern.topology), false);
  if (stop.stop_requested()) return std::nullopt;
  frame.elements = render::prepare_elements(
      placed.elements, render::element_colours(placed.elements, request.colour_mode, snapshot.design.elements.gap),
      request.custom_shape.get());
  if (request.with_pattern) frame.pattern = render::prepare_pattern(map, *snapshot.pattern, snapshot.points);
  return frame;
}

}  // namespace

struct LiveFrames::Slot {
  std::mutex mutex;
  bool busy = true;
  std::optional<LiveFrame> frame;
};

bool LiveFrames::busy() const {
  if (!slot_) return false;
  std::lock_guard lock(slot_->mutex);
  return slot_->busy;
}

void LiveFrames::prepare(LiveSnapshot snapshot, LiveFrameRequest request) {
  auto slot = std::make_shared<Slot>();
  slot_ = slot;
  jobs_.start([slot, snapshot = std::move(snapshot), request = std::move(request)](std::stop_token stop) {
    std::optional<LiveFrame> frame;
    try {
      frame = prepare_frame(snapshot, request, stop);
    } catch (const std::exception&) {
      // Nothing to show for this snapshot; the run itself reports what went wrong.
    }
    std::lock_guard lock(slot->mutex);
    slot->frame = std::move(frame);
    slot->busy = false;
  });
}

std::optional<LiveFrame> LiveFrames::take() {
  jobs_.reap();
  if (!slot_) return std::nullopt;
  std::lock_guard lock(slot_->mutex);
  return std::exchange(slot_->frame, std::nullopt);
}

void LiveFrames::reset() {
  jobs_.stop_all();
  jobs_.reap();
  slot_.reset();
}

}  // namespace paver::studio
