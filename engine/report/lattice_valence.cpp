#include "report/lattice_valence.h"

#include "elements/element_proximity.h"
#include "pattern/surface_triangulation.h"

#include <algorithm>
#include <utility>

namespace paver {

std::vector<int> lattice_valences(const Elements& elements, int regular_valence, double spacing) {
  if (regular_valence != 6) return vertex_valences(elements, kValenceShell);
  std::vector<int> valence(elements.size(), -1), vertex;
  std::vector<glm::dvec2> uv;
  std::vector<glm::dvec3> position;
  for (int i = 0; i < int(elements.size()); ++i)
    if (elements.kind[i] == ElementKind::Vertex) {
      vertex.push_back(i);
      uv.push_back(elements.uv[i]);
      position.push_back(elements.position[i]);
    }
  std::vector<std::pair<int, int>> edges;
  for (const glm::ivec3& t : triangulate_surface_points(uv, position, 2.5 * spacing))
    for (int k = 0; k < 3; ++k) edges.push_back(std::minmax(t[k], t[(k + 1) % 3]));
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  for (int v : vertex) valence[v] = 0;
  for (const auto& [a, b] : edges) ++valence[vertex[a]], ++valence[vertex[b]];
  return valence;
}

}  // namespace paver
