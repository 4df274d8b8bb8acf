#include "elements/elements.h"

namespace paver {

void Elements::clear() {
  id.clear();
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
  id.reserve(n);
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
  id.push_back(kNoElementId);
  kind.push_back(k);
  source.push_back(source_index);
  spec.push_back(spec_index);
  uv.push_back(uv_centre);
  position.push_back(centre);
  normal.push_back(unit_normal);
  diameter.push_back(element_diameter);
  shape.push_back(s);
}

namespace {

template <class T>
void erase_flagged_from(std::vector<T>& v, const std::vector<std::uint8_t>& remove) {
  std::size_t out = 0;
  for (std::size_t i = 0; i < v.size(); ++i)
    if (!remove[i]) v[out++] = v[i];
  v.resize(out);
}

template <class T>
void append_to(std::vector<T>& v, const std::vector<T>& more) {
  v.insert(v.end(), more.begin(), more.end());
}

}  // namespace

void Elements::erase_flagged(const std::vector<std::uint8_t>& remove) {
  erase_flagged_from(id, remove);
  erase_flagged_from(kind, remove);
  erase_flagged_from(source, remove);
  erase_flagged_from(spec, remove);
  erase_flagged_from(uv, remove);
  erase_flagged_from(position, remove);
  erase_flagged_from(normal, remove);
  erase_flagged_from(diameter, remove);
  erase_flagged_from(shape, remove);
}

void Elements::append(const Elements& other) {
  append_to(id, other.id);
  append_to(kind, other.kind);
  append_to(source, other.source);
  append_to(spec, other.spec);
  append_to(uv, other.uv);
  append_to(position, other.position);
  append_to(normal, other.normal);
  append_to(diameter, other.diameter);
  append_to(shape, other.shape);
}

}  // namespace paver
