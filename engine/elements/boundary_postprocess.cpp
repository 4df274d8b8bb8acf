#include "elements/boundary_postprocess.h"

#include "elements/cell_grid.h"

#include "map/lifting.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>

namespace paver {
namespace {

double cross2(glm::dvec2 a, glm::dvec2 b) { return a.x * b.y - a.y * b.x; }

// Parameter s in (0, 1] where segment p->q first meets the boundary of M^, or +inf.
double first_boundary_hit(const SurfaceMap& map, glm::dvec2 p, glm::dvec2 q) {
  const auto& loop = map.mesh.boundary_loop;
  const int n = int(loop.size());
  const glm::dvec2 d = q - p;
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < n; ++i) {
    const glm::dvec2 a = map.uv[loop[i]], b = map.uv[loop[(i + 1) % n]];
    const glm::dvec2 e = b - a;
    const double denom = cross2(d, e);
    if (denom == 0) continue;
    const double s = cross2(a - p, e) / denom;
    const double u = cross2(a - p, d) / denom;
    if (s > 0 && s <= 1 && u >= 0 && u <= 1) best = std::min(best, s);
  }
  return best;
}

double point_segment_distance(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 ab = b - a;
  const double len2 = glm::dot(ab, ab);
  const double t = len2 > 0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return glm::length(p - (a + t * ab));
}

}  // namespace

int fill_boundary_edges(const SurfaceMap& map, const Pattern& pattern, const std::vector<glm::dvec2>& points,
                        const ElementsDesign& design, double spacing, Elements& elements,
                        const std::vector<std::uint8_t>* retired) {
  // The pattern continues up to the boundary: an E-element keeps its t along the whole lattice
  // edge and is placed when it falls on the part inside the map.
  std::vector<glm::dvec2> centres;
  std::vector<std::pair<int, int>> origin;  // (crossing edge, spec)
  for (int c = 0; c < int(pattern.crossing_edges.size()); ++c) {
    const Pattern::CrossingEdge& edge = pattern.crossing_edges[c];
    if (retired && (*retired)[edge.inside_point]) continue;
    const glm::dvec2 inside = points[edge.inside_point];
    const glm::dvec2 outside = inside + (edge.outside - pattern.points[edge.inside_point]);
    const double hit = std::min(1.0, first_boundary_hit(map, inside, outside));
    const glm::dvec2 from = edge.inside_is_from ? inside : outside;
    const glm::dvec2 to = edge.inside_is_from ? outside : inside;
    for (int s = 0; s < int(design.edge.size()); ++s) {
      const EdgeElementDesign& spec = design.edge[s];
      if (!spec.cell_edges.empty() &&
          std::find(spec.cell_edges.begin(), spec.cell_edges.end(), edge.cell_edge) == spec.cell_edges.end())
        continue;
      // Distance along the edge from the inside end, as a fraction of the edge.
      const double from_inside = edge.inside_is_from ? spec.t : 1 - spec.t;
      if (from_inside >= hit) continue;
      centres.push_back(from + spec.t * (to - from));
      origin.emplace_back(c, s);
    }
  }
  LiftedPoints lifted;
  lifted.resize(centres.size());
  lift_points(map, centres, lifted);
  int added = 0;
  for (size_t i = 0; i < centres.size(); ++i) {
    if (lifted.triangle[i] < 0) continue;
    const EdgeElementDesign& spec = design.edge[origin[i].second];
    elements.push_back(ElementKind::Edge, -1 - origin[i].first, origin[i].second, centres[i], lifted.position[i],
                       lifted.normal[i], spec.scale * spacing, spec.shape);
    ++added;
  }
  return added;
}

std::vector<double> distances_to_boundary(const SurfaceMap& map, const Elements& elements) {
  const auto& loop = map.mesh.boundary_loop;
  const auto& pos = map.mesh.positions;
  const int n = int(loop.size());
  double cell = 0;
  for (double d : elements.diameter) cell = std::max(cell, d);
  // Cells no smaller than a quarter of the longest boundary segment, so a segment touches at most
  // a few cells even when the elements are tiny (a wider cell only checks more segments; distances
  // under one largest diameter stay exact).
  double longest = 0;
  for (int i = 0; i < n; ++i) longest = std::max(longest, glm::length(pos[loop[(i + 1) % n]] - pos[loop[i]]));
  const double cap = cell > 0 ? cell : 1;  // what farther elements report (documented in the header)
  // Boundary segments bucketed by the cells their bounding boxes touch; an element only needs
  // the segments within its radius (< one cell) of it; farther ones report at least `cell`.
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (int v : loop) lo = glm::min(lo, pos[v]), hi = glm::max(hi, pos[v]);
  for (const glm::dvec3& p : elements.position) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const CellGrid grid(lo, hi, std::max(cell, 0.25 * longest));
  const auto cell_of = [&](const glm::dvec3& p) { return grid.cell_of(p); };
  const auto key = CellGrid::key;
  std::unordered_map<std::uint64_t, std::vector<int>> buckets;
  for (int i = 0; i < n; ++i) {
    const glm::dvec3 a = pos[loop[i]], b = pos[loop[(i + 1) % n]];
    const glm::ivec3 c0 = cell_of(glm::min(a, b)), c1 = cell_of(glm::max(a, b));
    for (int z = c0.z; z <= c1.z; ++z)
      for (int y = c0.y; y <= c1.y; ++y)
        for (int x = c0.x; x <= c1.x; ++x) buckets[key({x, y, z})].push_back(i);
  }
  std::vector<double> distance(elements.size(), cap);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, elements.size(), 256), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t e = r.begin(); e != r.end(); ++e) {
      const glm::ivec3 c = cell_of(elements.position[e]);
      for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const auto it = buckets.find(key(c + glm::ivec3(dx, dy, dz)));
            if (it == buckets.end()) continue;
            for (int i : it->second)
              distance[e] = std::min(distance[e], point_segment_distance(elements.position[e], pos[loop[i]],
                                                                         pos[loop[(i + 1) % n]]));
          }
    }
  });
  return distance;
}

int eliminate_boundary_elements(const SurfaceMap& map, Elements& elements) {
  const std::vector<double> distance = distances_to_boundary(map, elements);
  std::vector<std::uint8_t> remove(elements.size(), 0);
  int removed = 0;
  for (size_t i = 0; i < elements.size(); ++i)
    if (distance[i] < 0.5 * elements.diameter[i]) remove[i] = 1, ++removed;
  elements.erase_flagged(remove);
  return removed;
}

}  // namespace paver
