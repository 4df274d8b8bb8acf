#pragma once
// The 2D view's image on screen and the map region it shows (y up, turned by the view's turn): map
// points to window pixels and back, for the view's mouse handling, its overlays and a script's clicks.
#include "renderer.h"

#include <glm/vec2.hpp>
#include <imgui.h>

namespace paver::studio {

struct MapFrame {
  ImVec2 origin, size;
  render::MapView view;
  // A window pixel's map point: its offset from the view's centre, in map units across the
  // screen, turned back by the view's turn.
  glm::dvec2 to_map(ImVec2 p) const {
    const double aspect = size.x / size.y;
    const glm::dvec2 on_screen((2.0 * (p.x - origin.x) / size.x - 1) * view.half_height * aspect,
                               (1 - 2.0 * (p.y - origin.y) / size.y) * view.half_height);
    return view.map_point(on_screen);
  }
  ImVec2 to_screen(glm::dvec2 q) const {
    const double aspect = size.x / size.y;
    const glm::dvec2 on_screen = view.screen_offset(q);
    return ImVec2(float(origin.x + (on_screen.x / (view.half_height * aspect) + 1) * 0.5 * size.x),
                  float(origin.y + (1 - on_screen.y / view.half_height) * 0.5 * size.y));
  }
  // A direction's angle on screen (radians, counter-clockwise, y up) from its angle in the map.
  double screen_angle(double map_angle) const { return map_angle + view.turn; }
};

}  // namespace paver::studio
