#include "elements/boundary_postprocess.h"

#include "elements/stone_grade.h"

#include "map/boundary_index.h"

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
double first_boundary_hit(const SurfaceMap& map, const std::vector<glm::ivec2>& segments, glm::dvec2 p, glm::dvec2 q) {
  const glm::dvec2 d = q - p;
  double best = std::numeric_limits<double>::infinity();
  for (const glm::ivec2& segment : segments) {
    // On a map that wraps: the segment in one piece, in the copy next to p.
    const glm::dvec2 a = nearest_image(map, map.uv[segment.x], p);
    const glm::dvec2 b = nearest_image(map, map.uv[segment.y], a);
    const glm::dvec2 e = b - a;
    const double denom = cross2(d, e);
    if (denom == 0) continue;
    const double s = cross2(a - p, e) / denom;
    const double u = cross2(a - p, d) / denom;
    if (s > 0 && s <= 1 && u >= 0 && u <= 1) best = std::min(best, s);
  }
  return best;
}

}  // namespace

int fill_boundary_edges(const SurfaceMap& map, const Pattern& pattern, const std::vector<glm::dvec2>& points,
                        const ElementsDesign& design, double spacing, Elements& elements,
                        const std::vector<std::uint8_t>* retired) {
  // The pattern continues up to the boundary: an E-element keeps its t along the whole lattice
  // edge and is placed when it falls on the part inside the map.
  const std::vector<glm::ivec2> segments = boundary_segments(map.mesh);
  std::vector<glm::dvec2> centres;
  std::vector<std::pair<int, int>> origin;  // (crossing edge, spec)
  for (int c = 0; c < int(pattern.crossing_edges.size()); ++c) {
    const Pattern::CrossingEdge& edge = pattern.crossing_edges[c];
    if (retired && (*retired)[edge.inside_point]) continue;
    const glm::dvec2 inside = points[edge.inside_point];
    const glm::dvec2 outside = inside + (edge.outside - pattern.points[edge.inside_point]);
    const double hit = std::min(1.0, first_boundary_hit(map, segments, inside, outside));
    const glm::dvec2 from = edge.inside_is_from ? inside : outside;
    const glm::dvec2 to = edge.inside_is_from ? outside : inside;
    for (int s = 0; s < int(design.edge.size()); ++s) {
      const EdgeElementDesign& spec = design.edge[s];
      if (!spec.sits_on(edge.cell_edge)) continue;
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

std::vector<double> distances_to_boundary(const SurfaceMap& map, const Elements& elements, double reach) {
  double cap = 0;
  for (double d : elements.diameter) cap = std::max(cap, d);
  cap += std::max(reach, 0.0);
  // Only near elements matter: farther ones than the cap report it.
  const BoundaryIndex boundary(map.mesh, cap > 0 ? cap : 1);
  std::vector<double> distance(elements.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, elements.size(), 256), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t e = r.begin(); e != r.end(); ++e) distance[e] = boundary.nearest(elements.position[e]).distance;
  });
  return distance;
}

int eliminate_boundary_elements(const SurfaceMap& map, Elements& elements, double margin) {
  const std::vector<double> distance = distances_to_boundary(map, elements, margin);
  std::vector<std::uint8_t> remove(elements.size(), 0);
  int removed = 0;
  for (size_t i = 0; i < elements.size(); ++i)
    if (!keeps_margin(distance[i], elements.diameter[i], margin)) remove[i] = 1, ++removed;
  elements.erase_flagged(remove);
  return removed;
}

PlacedElements place_all_elements(const SurfaceMap& map, const Pattern& pattern, const std::vector<glm::dvec2>& points,
                                  const ElementsDesign& design, double spacing, EdgeAnchor anchor, bool postprocess,
                                  const std::vector<std::uint8_t>* retired, const GradeField* grade) {
  PlacedElements placed;
  placed.elements = place_elements(map, pattern, points, design, spacing, retired, anchor);
  if (grade) grade_stones(map, *grade, placed.elements);
  if (postprocess) {
    placed.filled = fill_boundary_edges(map, pattern, points, design, spacing, placed.elements, retired);
    placed.eliminated =
        eliminate_boundary_elements(map, placed.elements, boundary_margin(map, design.margin, design.gap));
  }
  return placed;
}

}  // namespace paver
