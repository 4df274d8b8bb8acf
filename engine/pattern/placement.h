#pragma once
// How the 2D map M^ sits under the pattern U^ (section 4.2): the map is scaled, rotated and then
// translated into the pattern plane. Pattern point p and map point q relate by
//   p = R(rotation) * (scale * q) + offset.
#include <glm/vec2.hpp>

namespace paver {

struct Placement {
  glm::dvec2 offset{0, 0};   // pattern-plane units (same as D); default 0
  double rotation_deg = 0;   // degrees, counter-clockwise; default 0
  double scale = 1;          // > 0; default 1 (the map keeps the surface's area)

  glm::dvec2 map_to_pattern(glm::dvec2 q) const;
  glm::dvec2 pattern_to_map(glm::dvec2 p) const;
};

}  // namespace paver
