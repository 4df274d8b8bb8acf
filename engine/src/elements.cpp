#include "paver/elements.h"

namespace paver {

void Elements::clear() {
  kind.clear();
  source.clear();
  spec.clear();
  uv.clear();
  position.clear();
  normal.clear();
  diameter.clear();
  shape.clear();
}

void Elements::reserve(std::size_t n) {
  kind.reserve(n);
  source.reserve(n);
  spec.reserve(n);
  uv.reserve(n);
  position.reserve(n);
  normal.reserve(n);
  diameter.reserve(n);
  shape.reserve(n);
}

void Elements::push_back(ElementKind k, int source_index, int spec_index, glm::dvec2 uv_centre,
                         glm::dvec3 centre, glm::dvec3 unit_normal, double element_diameter,
                         ShapeKind s) {
  kind.push_back(k);
  source.push_back(source_index);
  spec.push_back(spec_index);
  uv.push_back(uv_centre);
  position.push_back(centre);
  normal.push_back(unit_normal);
  diameter.push_back(element_diameter);
  shape.push_back(s);
}

}  // namespace paver
