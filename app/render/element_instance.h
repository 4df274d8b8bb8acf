#pragma once
// One element as the 3D view's instance buffer holds it: the frame comes from the engine's
// element_frame, the rule the exporters use, so shaders/element.vert only applies it
// (centre + diameter * (v.x t + v.y b + v.z n)) and the preview shows what is exported.
#include "elements/elements.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>

namespace paver::render {

struct ElementInstance {
  glm::vec3 centre;
  float diameter;
  glm::vec3 tangent;
  std::uint32_t colour;  // RGBA8
  glm::vec3 bitangent;
  glm::vec3 normal;
};
static_assert(sizeof(ElementInstance) == 56);

ElementInstance make_element_instance(const Elements& elements, std::size_t i, std::uint32_t colour);

// What shaders/element.vert computes for shape vertex `v` of the instance (for tests).
glm::vec3 instance_vertex(const ElementInstance& instance, const glm::vec3& v);

}  // namespace paver::render
