#include "element_instance.h"

#include "elements/element_frame.h"

namespace paver::render {

ElementInstance make_element_instance(const Elements& elements, std::size_t i, std::uint32_t colour) {
  const ElementFrame f = element_frame(elements.normal[i]);
  return {glm::vec3(elements.position[i]), float(elements.diameter[i]), glm::vec3(f.t), colour, glm::vec3(f.b),
          glm::vec3(f.n)};
}

glm::vec3 instance_vertex(const ElementInstance& e, const glm::vec3& v) {
  const glm::vec3 local = v * e.diameter;
  return e.centre + local.x * e.tangent + local.y * e.bitangent + local.z * e.normal;
}

}  // namespace paver::render
