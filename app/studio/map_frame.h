#pragma once
// The 2D view's image on screen and the map region it shows (y up): map points to window pixels
// and back, for the view's mouse handling, its overlays and a script's clicks.
#include "renderer.h"

#include <glm/vec2.hpp>
#include <imgui.h>

namespace paver::studio {

struct MapFrame {
  ImVec2 origin, size;
  render::MapView view;
  glm::dvec2 to_map(ImVec2 p) const {
    const double aspect = size.x / size.y;
    return {view.centre.x + (2.0 * (p.x - origin.x) / size.x - 1) * view.half_height * aspect,
            view.centre.y + (1 - 2.0 * (p.y - origin.y) / size.y) * view.half_height};
  }
  ImVec2 to_screen(glm::dvec2 q) const {
    const double aspect = size.x / size.y;
    return ImVec2(float(origin.x + ((q.x - view.centre.x) / (view.half_height * aspect) + 1) * 0.5 * size.x),
                  float(origin.y + (1 - (q.y - view.centre.y) / view.half_height) * 0.5 * size.y));
  }
};

}  // namespace paver::studio
