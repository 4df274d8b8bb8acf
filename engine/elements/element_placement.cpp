#include "elements/element_placement.h"

#include "map/lifting.h"
#include "map/surface_particles.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace paver {
namespace {

constexpr int kChordSteps = 4;  // tangent steps from the map's point towards the chord's

}  // namespace

Elements place_elements(const SurfaceMap& map, const Pattern& pattern,
                        const std::vector<glm::dvec2>& points, const ElementsDesign& design,
                        double spacing, const std::vector<std::uint8_t>* retired, EdgeAnchor anchor) {
  // Gather every element centre in 2D first, then lift them in one parallel call.
  struct Pending {
    ElementKind kind;
    int source, spec;
    double diameter;
    ShapeKind shape;
  };
  std::vector<Pending> pending;
  std::vector<glm::dvec2> centres;
  std::vector<glm::dvec3> chord_points;  // SurfaceChord: where each E-element aims, in 3D
  LiftedPoints ends;
  if (anchor == EdgeAnchor::SurfaceChord && !design.edge.empty()) {
    ends.resize(points.size());
    lift_points(map, points, ends);
  }
  if (design.vertex.enabled)
    for (int p = 0; p < pattern.point_count(); ++p) {
      if (retired && (*retired)[p]) continue;
      pending.push_back({ElementKind::Vertex, p, 0, design.vertex.scale * spacing, design.vertex.shape});
      centres.push_back(points[p]);
    }
  for (int s = 0; s < int(design.edge.size()); ++s) {
    const EdgeElementDesign& spec = design.edge[s];
    for (int e = 0; e < pattern.edge_count(); ++e) {
      if (pattern.edge_virtual[e] || !spec.sits_on(pattern.edge_cell_edge[e])) continue;
      const glm::dvec2 a = points[pattern.edge_a[e]];
      const glm::dvec2 b = nearest_image(map, points[pattern.edge_b[e]], a);  // across a band's seam
      pending.push_back({ElementKind::Edge, e, s, spec.scale * spacing, spec.shape});
      centres.push_back(a + spec.t * (b - a));
      if (anchor != EdgeAnchor::SurfaceChord) continue;
      const int ia = pattern.edge_a[e], ib = pattern.edge_b[e];
      const bool lifted_ends = ends.triangle[ia] >= 0 && ends.triangle[ib] >= 0;
      chord_points.push_back(lifted_ends ? ends.position[ia] + spec.t * (ends.position[ib] - ends.position[ia])
                                         : glm::dvec3(std::nan("")));
    }
  }
  if (!chord_points.empty()) {
    // From the map's point, a few tangent steps towards the chord point: they end where the
    // surface is nearest it. The E-elements follow the V-elements in `centres`.
    const size_t first_edge = centres.size() - chord_points.size();
    SurfaceParticles on_surface;
    on_surface.uv.assign(centres.begin() + first_edge, centres.end());
    on_surface.lifted.resize(chord_points.size());
    lift_points(map, on_surface.uv, on_surface.lifted);
    for (int attempt = 0; attempt < kChordSteps; ++attempt) {
      std::vector<glm::dvec3> step(chord_points.size(), glm::dvec3(0));
      for (size_t k = 0; k < chord_points.size(); ++k)
        if (!std::isnan(chord_points[k].x)) step[k] = chord_points[k] - on_surface.lifted.position[k];
      on_surface.step(map, std::move(step));
    }
    std::copy(on_surface.uv.begin(), on_surface.uv.end(), centres.begin() + first_edge);
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
