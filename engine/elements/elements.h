#pragma once
// The instantiated elements of a pavement: one entry per V- or E-element, as structs of arrays.
#include "elements/element_shape.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace paver {

// Vertex, Edge and Face elements are the pattern's (stones); a Bead is a small metal prong between three
// stones (elements/beads.h), kept apart from them and added only to the exported meshes.
enum class ElementKind : std::uint8_t { Vertex, Edge, Bead, Face };

// The colour each kind is drawn and exported in (the paper's figure 4: V blue, E orange; F green,
// a third the figure did not need; beads gold, the metal's), the same in the PLY, the glTF, the studio and the PNGs.
inline std::array<std::uint8_t, 3> kind_colour(ElementKind kind) {
  switch (kind) {
    case ElementKind::Vertex: return {52, 101, 164};
    case ElementKind::Edge: return {237, 125, 49};
    case ElementKind::Bead: return {212, 175, 55};
    case ElementKind::Face: return {84, 160, 82};
  }
  return {128, 128, 128};
}

// The id of an element that number_elements (elements/element_ids.h) has not named yet.
inline constexpr int kNoElementId = -1;

struct Elements {
  std::vector<int> id;              // stable id (elements/element_ids.h); kNoElementId until numbered
  std::vector<ElementKind> kind;
  std::vector<int> source;          // pattern point (V), pattern edge (E), pattern face (F), or -1 - crossing edge (filling)
  std::vector<int> spec;            // index into the design's edge-element list (E), 0 for V
  std::vector<glm::dvec2> uv;       // centre in the map's parameter plane
  std::vector<glm::dvec3> position; // centre on the surface
  std::vector<glm::dvec3> normal;   // unit surface normal at the centre
  std::vector<double> diameter;     // element diameter, surface units
  std::vector<ShapeKind> shape;

  std::size_t size() const { return kind.size(); }
  void clear();
  void reserve(std::size_t n);
  void push_back(ElementKind k, int source_index, int spec_index, glm::dvec2 uv_centre,
                 glm::dvec3 centre, glm::dvec3 unit_normal, double element_diameter, ShapeKind s);
  // Removes element i wherever remove[i] is non-zero, keeping the order of the rest.
  void erase_flagged(const std::vector<std::uint8_t>& remove);
  void append(const Elements& other);
};

}  // namespace paver
