#include "report/lattice_valence.h"

#include "elements/element_proximity.h"
#include "pattern/surface_triangulation.h"

#include <algorithm>
#include <cmath>
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
  // Across a seam: the points near either end of the period once more, a period further; an edge
  // counts once, between the points it joins. Only a strip is copied (a few edge lengths wide,
  // with room for the map's distortion): copying every point tripled the triangulation, the bulk
  // of a band's quality measure.
  const int n = int(vertex.size());
  std::vector<int> origin(n);
  for (int i = 0; i < n; ++i) origin[i] = i;
  if (period > 0 && n > 0) {
    // Into one period first: refill may leave a point's u past the period's end.
    double lo = uv[0].x;
    for (int i = 0; i < n; ++i) lo = std::min(lo, uv[i].x);
    for (int i = 0; i < n; ++i) uv[i].x = lo + std::fmod(uv[i].x - lo, period);
    double hi = lo;
    for (int i = 0; i < n; ++i) hi = std::max(hi, uv[i].x);
    const double reach = std::min(8 * spacing, period);
    for (int i = 0; i < n; ++i) {
      if (uv[i].x < lo + reach) uv.push_back(uv[i] + glm::dvec2(period, 0)), position.push_back(position[i]), origin.push_back(i);
      if (uv[i].x > hi - reach) uv.push_back(uv[i] - glm::dvec2(period, 0)), position.push_back(position[i]), origin.push_back(i);
    }
  }
  std::vector<std::pair<int, int>> edges;
  for (const glm::ivec3& t : triangulate_surface_points(uv, position, 2.5 * spacing))
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      if (a >= n && b >= n) continue;  // between two copies
      if (origin[a] == origin[b]) continue;  // a point and its own copy (a band one edge long)
      edges.push_back(std::minmax(origin[a], origin[b]));
    }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  for (int v : vertex) valence[v] = 0;
  for (const auto& [a, b] : edges) ++valence[vertex[a]], ++valence[vertex[b]];
  return valence;
}

}  // namespace paver
