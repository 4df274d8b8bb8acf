#include "scene.h"

namespace paver::studio {

bool sync_scene(Scene& scene, render::Renderer& renderer, Document& doc, const LivePavement& live,
                const ViewSettings& views) {
  const SurfaceMap* map = doc.surface.map.get();
  if (!map) return false;
  // The map the points are on (a band's seamless map or its annulus), drawn once it changes;
  // the elements are uploaded after it.
  const auto show_map = [&](const SurfaceMap& shown) {
    if (scene.map_2d == &shown) return;
    renderer.set_surface(shown);
    scene.map_2d = &shown;
  };
  if (scene.surface != map) {
    renderer.set_surface(*map);
    renderer.set_elements({}, {});
    scene.surface = map;
    scene.map_2d = map;
    scene.pavement = nullptr;
    scene.live_sequence = 0;
    scene.lattice_uploaded = false;
    scene.live_frames.reset();
    ++scene.generation;
  }
  // Set where elements are uploaded: a live frame prepared before the colouring changed is drawn in
  // the old colours, and asks for another.
  const bool recolour = scene.colour_mode != views.colour_mode;
  // The pattern's lines are uploaded only while they are shown: lifting them for the 3D view is
  // most of a live upload's time (46k elements: 30-80 ms of 100), on every upload of a run.
  const bool lattice_shown = views.style.show_lattice;
  const bool lattice_missing = lattice_shown && !scene.lattice_uploaded;

  // A run in progress for this revision (a new design, or Run / Step again): its particles as
  // they move. Otherwise the final pavement.
  const RunState state = live.state();
  if ((state == RunState::Running || state == RunState::Paused) && live.revision() == doc.revision) {
    // A frame prepared off the UI thread (live_frames.h) is shown as it comes.
    if (std::optional<LiveFrame> frame = scene.live_frames.take()) {
      if (frame->revision != doc.revision) return false;
      show_map(map_for_topology(*map, frame->topology));
      renderer.set_elements(frame->elements);
      scene.colour_mode = frame->colour_mode;
      // Without the lines, the last ones are dropped: they are not this frame's.
      renderer.set_pattern(frame->pattern ? *frame->pattern : render::PreparedPattern{});
      scene.lattice_uploaded = frame->pattern.has_value();
      scene.pavement = nullptr;
      scene.live_sequence = frame->sequence;
      ++scene.generation;
      return false;
    }
    if (scene.live_frames.busy()) return false;
    const auto now = std::chrono::steady_clock::now();
    const bool again = recolour || lattice_missing;
    if (!again && scene.live_sequence != 0 && now - scene.live_uploaded < kLiveInterval) return false;
    // The views are still drawing the last frame: a new one now would restart them, and they
    // would never finish. A view that moves (its drawing not begun: each frame it draws a quick
    // image instead) does not hold the live view up.
    if (!again && (renderer.drawing_begun(0) || renderer.drawing_begun(1))) return false;
    std::optional<LiveSnapshot> snapshot = live.snapshot_since(again ? 0 : scene.live_sequence);
    if (!snapshot || snapshot->revision != doc.revision) return false;
    scene.live_frames.prepare(std::move(*snapshot),
                              {doc.surface.map, shared_custom_shape(doc), views.colour_mode, lattice_shown});
    scene.live_uploaded = now;
    return false;
  }
  scene.live_frames.reset();  // a frame of a run no longer shown

  const PavementResult& result = doc.result;
  if (!result.pavement || result.revision != doc.revision) return false;
  const Pavement& p = *result.pavement;
  if (scene.pavement == &p && !recolour && !lattice_missing) return false;
  auto colours = render::element_colours(p.elements, views.colour_mode, p.design.elements.gap);
  scene.colour_mode = views.colour_mode;
  Elements with_beads;  // drawn with the stones, as they are exported; stone i stays element i
  show_map(pavement_map(*map, p));
  renderer.set_elements(stones_and_beads(p, with_beads, &colours), colours, custom_shape(doc));
  if (lattice_shown) renderer.set_pattern(*scene.map_2d, p.pattern, p.points);
  scene.lattice_uploaded = lattice_shown;
  const bool first_upload = scene.pavement != &p;
  scene.pavement = &p;
  ++scene.generation;
  return first_upload && result.latency_ms < 0;
}

}  // namespace paver::studio
