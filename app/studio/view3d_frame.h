#pragma once
// The 3D view's image on screen and its camera: surface points to window pixels, and a pixel to
// the ray through it (for a stone dragged along the surface), for the view and a script's drags.
#include "renderer.h"

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <glm/vec3.hpp>
#include <imgui.h>

#include <cmath>
#include <optional>
#include <utility>

namespace paver::studio {

struct View3dFrame {
  ImVec2 origin, size;
  glm::mat4 vp;    // the camera's view-projection at this size
  glm::dvec3 eye;  // the camera's position

  View3dFrame(ImVec2 o, ImVec2 s, const render::OrbitCamera& camera)
      : origin(o), size(s), vp(camera.view_projection(s.x / s.y)), eye(camera.eye()) {}

  // Where `p` shows (none behind the camera).
  std::optional<ImVec2> to_screen(glm::dvec3 p) const {
    const glm::vec4 clip = vp * glm::vec4(glm::vec3(p), 1);
    if (clip.w <= 0) return std::nullopt;
    return ImVec2(origin.x + (clip.x / clip.w + 1) * 0.5f * size.x, origin.y + (1 - clip.y / clip.w) * 0.5f * size.y);
  }
  // The on-screen radius of an element's footprint (a disc of `diameter` at `p` facing `normal`,
  // shown at `centre`): from a point half a diameter across the view.
  float footprint_radius(glm::dvec3 p, glm::dvec3 normal, double diameter, ImVec2 centre) const {
    const glm::dvec3 side = glm::normalize(glm::cross(eye - p, normal));
    const std::optional<ImVec2> edge = to_screen(p + 0.5 * diameter * side);
    return edge ? std::hypot(edge->x - centre.x, edge->y - centre.y) : 4.0f;
  }
  // The ray through pixel `at`: a point on the near plane and a direction into the scene.
  std::pair<glm::dvec3, glm::dvec3> ray(ImVec2 at) const {
    const float x = 2 * (at.x - origin.x) / size.x - 1, y = 1 - 2 * (at.y - origin.y) / size.y;
    const glm::mat4 inverse = glm::inverse(vp);
    const glm::vec4 near = inverse * glm::vec4(x, y, 0, 1), far = inverse * glm::vec4(x, y, 0.5f, 1);
    const glm::dvec3 a = glm::dvec3(glm::vec3(near) / near.w), b = glm::dvec3(glm::vec3(far) / far.w);
    return {a, b - a};
  }
};

}  // namespace paver::studio
