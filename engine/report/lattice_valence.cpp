#include "report/lattice_valence.h"

#include "elements/element_proximity.h"
#include "pattern/surface_triangulation.h"

#include <algorithm>
#include <utility>

namespace paver {

std::vector<int> lattice_valences(const Elements& elements, int regular_valence, double spacing, double period) {
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
  // Across a seam: the points once more a period to either side; an edge counts once, between the
  // points it joins.
  const int n = int(vertex.size());
  if (period > 0)
    for (const double shift : {-period, period})
      for (int i = 0; i < n; ++i) {
        uv.push_back(uv[i] + glm::dvec2(shift, 0));
        position.push_back(position[i]);
      }
  std::vector<std::pair<int, int>> edges;
  for (const glm::ivec3& t : triangulate_surface_points(uv, position, 2.5 * spacing))
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      if (a >= n && b >= n) continue;  // between two copies
      edges.push_back(std::minmax(a % n, b % n));
    }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  for (int v : vertex) valence[v] = 0;
  for (const auto& [a, b] : edges) ++valence[vertex[a]], ++valence[vertex[b]];
  return valence;
}

}  // namespace paver
