#include "elements/element_placement.h"

#include "map/lifting.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace paver {
namespace {

bool on_cell_edge(const EdgeElementDesign& spec, int cell_edge) {
  return spec.cell_edges.empty() ||
         std::find(spec.cell_edges.begin(), spec.cell_edges.end(), cell_edge) != spec.cell_edges.end();
}

}  // namespace

Elements place_elements(const SurfaceMap& map, const Pattern& pattern,
                        const std::vector<glm::dvec2>& points, const ElementsDesign& design,
                        double spacing, const std::vector<std::uint8_t>* retired) {
  // Gather every element centre in 2D first, then lift them in one parallel call.
  struct Pending {
    ElementKind kind;
    int source, spec;
    double diameter;
    ShapeKind shape;
  };
  std::vector<Pending> pending;
  std::vector<glm::dvec2> centres;
  if (design.vertex.enabled)
    for (int p = 0; p < pattern.point_count(); ++p) {
      if (retired && (*retired)[p]) continue;
      pending.push_back({ElementKind::Vertex, p, 0, design.vertex.scale * spacing, design.vertex.shape});
      centres.push_back(points[p]);
    }
  for (int s = 0; s < int(design.edge.size()); ++s) {
    const EdgeElementDesign& spec = design.edge[s];
    for (int e = 0; e < pattern.edge_count(); ++e) {
      if (pattern.edge_virtual[e] || !on_cell_edge(spec, pattern.edge_cell_edge[e])) continue;
      const glm::dvec2 a = points[pattern.edge_a[e]], b = points[pattern.edge_b[e]];
      pending.push_back({ElementKind::Edge, e, s, spec.scale * spacing, spec.shape});
      centres.push_back(a + spec.t * (b - a));
    }
  }
  LiftedPoints lifted;
  lifted.resize(centres.size());
  lift_points(map, centres, lifted);

  Elements elements;
  elements.reserve(pending.size());
  for (size_t i = 0; i < pending.size(); ++i) {
    // An E-element on an edge that bends outside a concave boundary has no surface point.
    if (lifted.triangle[i] < 0) continue;
    const Pending& p = pending[i];
    elements.push_back(p.kind, p.source, p.spec, centres[i], lifted.position[i], lifted.normal[i],
                       p.diameter, p.shape);
  }
  return elements;
}

}  // namespace paver
