#pragma once
// Keeps what the renderer shows in step with the document and the live run: the surface, and
// either the live particles (elements placed on them as they move) or the final pavement.
// Uploads only what changed; `generation` bumps with every upload so the views draw again.
#include "document.h"
#include "live_frames.h"
#include "live_pavement.h"
#include "view_settings.h"

#include "renderer.h"

#include <array>
#include <chrono>
#include <cstdint>
#include <vector>

namespace paver::studio {

// How long a view's full image takes to draw, and how the studio drew them (views_panel.cpp).
struct ViewPace {
  double full_image_ms = 0;   // the last whole image's drawing time
  int quick_images = 0, images_in_slices = 0;
};

struct Scene {
  const SurfaceMap* surface = nullptr;    // the map last uploaded
  const SurfaceMap* map_2d = nullptr;     // the map drawn (a band's seamless map when its points are on it)
  const Pavement* pavement = nullptr;     // the final pavement last uploaded; null while live
  std::uint64_t live_sequence = 0;        // the live snapshot last uploaded
  LiveFrames live_frames;                 // the next one, prepared off the UI thread
  bool lattice_uploaded = false;          // the pattern's lines match the elements uploaded
  std::chrono::steady_clock::time_point live_uploaded{};  // when the last was taken: at most one per kLiveInterval
  render::ColourMode colour_mode = render::ColourMode::NeighbourRatio;
  std::uint64_t generation = 0;
  std::array<std::vector<double>, 2> rendered;  // per view: the inputs its image was drawn with
  std::array<std::vector<double>, 2> drawing;   // per view: those of the image drawn in slices, if any
  std::array<ViewPace, 2> pace;
  std::array<bool, 2> redraw_whole{false, false};  // the view's image was replaced: draw it whole
};

// A live snapshot is shown at most this often, and only once the views finished drawing the last.
inline constexpr auto kLiveInterval = std::chrono::milliseconds(150);
// How long a frame may spend drawing slices of each view's next image (views_panel.cpp): with the
// rest of a frame at about 25 ms on lavapipe, the frame stays within 33 ms (30 fps).
inline constexpr double kViewSliceBudgetMs = 3;
// A view whose full image took longer than this is drawn in slices while it moves, after a quick
// image without the elements (views_panel.cpp).
inline constexpr double kQuickImageAboveMs = 20;
// Ends Scene::rendered[view] while the view shows such a quick image (a generation is never < 0).
inline constexpr double kQuickImageMark = -1;

// Returns true when the document's final pavement was uploaded this frame: once it is presented,
// the edit-to-result latency is known.
bool sync_scene(Scene& scene, render::Renderer& renderer, Document& doc, const LivePavement& live,
                const ViewSettings& views);

}  // namespace paver::studio
