#include "elements/element_ids.h"

#include <algorithm>

namespace paver {

int first_refill_id(const Pattern& pattern) {
  return pattern.designed_point_count() + pattern.edge_count() + int(pattern.crossing_edges.size()) +
         pattern.face_count();
}

void number_elements(Elements& elements, const Pattern& pattern, const std::vector<AddedElement>& added) {
  const int designed = pattern.designed_point_count();
  const int edges = pattern.edge_count();
  int next_refill = first_refill_id(pattern);
  for (std::size_t i = 0; i < elements.size(); ++i) {
    const int source = elements.source[i];
    int& id = elements.id[i];
    switch (elements.kind[i]) {
      case ElementKind::Vertex:
        if (source < 0)
          id = next_refill++;
        else
          id = source < designed ? source : added.at(std::size_t(source - designed)).id;
        break;
      case ElementKind::Edge:
        id = source >= 0 ? designed + source : designed + edges + (-1 - source);
        break;
      case ElementKind::Face:
        id = designed + edges + int(pattern.crossing_edges.size()) + source;
        break;
      case ElementKind::Bead:
        break;  // number_beads
    }
  }
}

void number_beads(Elements& beads, const Elements& stones) {
  int next = 0;
  for (const int id : stones.id)
    if (id < kFirstAddedId) next = std::max(next, id + 1);
  for (int& id : beads.id) id = next++;
}

}  // namespace paver
