#pragma once
// How the two views look: the 3D orbit camera, the 2D map view, what is drawn and how elements
// are coloured, and which view is the large one.
#include "renderer.h"

#include <glm/vec2.hpp>

namespace paver::studio {

struct ViewSettings {
  render::OrbitCamera camera;
  render::MapView map_view;
  render::SceneStyle style;
  render::ColourMode colour_mode = render::ColourMode::NeighbourRatio;
  bool large_3d = true;      // the 3D view fills the main area, the 2D view is the inset (or the reverse)
  bool show_legend = true;   // the legend of the colouring, over the large view
  bool show_inset = true;    // the other view in the large view's bottom-right corner
  bool show_flaws = true;    // the final pavement's bare spots and removed stones, marked in both views
  // The 2D map turned as the 3D view shows the surface (render::map_turn_to_match), again each
  // time the camera comes to rest; off, the map's u runs across the screen.
  bool map_follows_3d = true;
  glm::vec2 map_turned_for{0};  // the camera's yaw and pitch the map's turn was found for
  glm::vec2 last_look{0};       // the camera's yaw and pitch in the frame before
  float side_width = 0;      // the side panels' width in pixels once the splitter dragged it; 0: 430 (40% at most)
  double map_aspect = 1.6;   // width / height of the views' area, last drawn: the 2D view frames the whole map in it
  // Where the large view was last drawn, window pixels: a script's clicks at map points land there.
  glm::vec2 large_origin{0}, large_size{0};
};

// The share of the views' area that the inset takes, across and down.
inline constexpr float kInsetFraction = 0.32f;

}  // namespace paver::studio
