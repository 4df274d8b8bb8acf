#include "elements/element_placement.h"

#include "map/lifting.h"
#include "map/surface_particles.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace paver {
namespace {

constexpr int kChordSteps = 4;  // tangent steps from the map's point towards the chord's
constexpr int kSettleSteps = 24;  // an F-element's steps towards the middle of its corners' stones

// The surface's local linear map at a uv point of triangle t: the 3D step of a uv step.
struct LocalMetric {
  glm::dvec3 du{1, 0, 0}, dv{0, 1, 0};
  double length(glm::dvec2 step) const { return glm::length(du * step.x + dv * step.y); }
};

LocalMetric local_metric(const SurfaceMap& map, int t) {
  const glm::ivec3 tri = map.mesh.triangles[std::size_t(t)];
  const glm::dvec2 e1 = map.uv[std::size_t(tri[1])] - map.uv[std::size_t(tri[0])];
  const glm::dvec2 e2 = map.uv[std::size_t(tri[2])] - map.uv[std::size_t(tri[0])];
  const glm::dvec3 f1 = map.mesh.positions[std::size_t(tri[1])] - map.mesh.positions[std::size_t(tri[0])];
  const glm::dvec3 f2 = map.mesh.positions[std::size_t(tri[2])] - map.mesh.positions[std::size_t(tri[0])];
  const double det = e1.x * e2.y - e1.y * e2.x;
  if (!(std::abs(det) > 0)) return {};
  // [f1 f2] = [du dv] [e1 e2]: [du dv] = [f1 f2] [e1 e2]^-1.
  return {(f1 * e2.y - f2 * e1.y) / det, (f2 * e1.x - f1 * e2.x) / det};
}

// Where an F-element keeps the most room from its corners' stones (radius `corner_radius`): from
// the corners' mean, steps away from the nearest stone until the nearest two are as near. In a
// regular face this is the mean itself; in one the map sheared, the element keeps its share of the
// room on the surface instead of touching the corner the shear brought closer.
glm::dvec2 settle_in_face(const LocalMetric& metric, glm::dvec2 start, const std::vector<glm::dvec2>& corners,
                          double corner_radius) {
  const auto room = [&](glm::dvec2 x, int* nearest, double* second) {
    double best = std::numeric_limits<double>::infinity(), next = best;
    for (int k = 0; k < int(corners.size()); ++k) {
      const double d = metric.length(x - corners[std::size_t(k)]) - corner_radius;
      if (d < best) next = best, best = d, *nearest = k;
      else next = std::min(next, d);
    }
    *second = next;
    return best;
  };
  glm::dvec2 x = start;
  int nearest = 0;
  double second = 0;
  double best_room = room(x, &nearest, &second);
  glm::dvec2 best_x = x;
  for (int step = 0; step < kSettleSteps; ++step) {
    const glm::dvec2 away = x - corners[std::size_t(nearest)];
    const double away_length = metric.length(away);
    if (!(away_length > 0)) break;
    const double move = 0.5 * (second - best_room) * (1.0 - double(step) / kSettleSteps);
    if (!(move > 1e-9 * away_length)) break;
    x += away * (move / away_length);
    const double r = room(x, &nearest, &second);
    if (r > best_room) best_room = r, best_x = x;
  }
  return best_x;
}

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
  // F-elements after the E-elements (the chord steps below index them from the end of the
  // V-elements): at the mean of their face's corners, which carry them.
  const size_t first_face = centres.size();
  if (design.face.enabled)
    for (int f = 0; f < pattern.face_count(); ++f) {
      const int begin = pattern.face_start[std::size_t(f)], end = pattern.face_start[std::size_t(f) + 1];
      const glm::dvec2 first = points[std::size_t(pattern.face_corner[std::size_t(begin)])];
      glm::dvec2 sum(0);
      for (int k = begin; k < end; ++k)
        sum += nearest_image(map, points[std::size_t(pattern.face_corner[std::size_t(k)])], first);  // across a seam
      pending.push_back({ElementKind::Face, f, 0, design.face.scale * spacing, design.face.shape});
      centres.push_back(sum / double(end - begin));
    }
  if (!chord_points.empty()) {
    // From the map's point, a few tangent steps towards the chord point: they end where the
    // surface is nearest it. The E-elements follow the V-elements in `centres`.
    const size_t first_edge = first_face - chord_points.size();
    SurfaceParticles on_surface;
    on_surface.uv.assign(centres.begin() + std::ptrdiff_t(first_edge), centres.begin() + std::ptrdiff_t(first_face));
    on_surface.lifted.resize(chord_points.size());
    lift_points(map, on_surface.uv, on_surface.lifted);
    for (int attempt = 0; attempt < kChordSteps; ++attempt) {
      std::vector<glm::dvec3> step(chord_points.size(), glm::dvec3(0));
      for (size_t k = 0; k < chord_points.size(); ++k)
        if (!std::isnan(chord_points[k].x)) step[k] = chord_points[k] - on_surface.lifted.position[k];
      on_surface.step(map, std::move(step));
    }
    std::copy(on_surface.uv.begin(), on_surface.uv.end(), centres.begin() + std::ptrdiff_t(first_edge));
  }
  LiftedPoints lifted;
  lifted.resize(centres.size());
  lift_points(map, centres, lifted);
  if (design.face.enabled && design.vertex.enabled) {
    // Each F-element settles where its corners' stones leave it the most room, and is lifted again.
    std::vector<glm::dvec2> corners;
    std::vector<std::size_t> moved;
    for (std::size_t i = first_face; i < centres.size(); ++i) {
      if (lifted.triangle[i] < 0) continue;
      const int f = pending[i].source;
      const int begin = pattern.face_start[std::size_t(f)], end = pattern.face_start[std::size_t(f) + 1];
      corners.clear();
      for (int k = begin; k < end; ++k) {
        const int p = pattern.face_corner[std::size_t(k)];
        if (!(retired && (*retired)[std::size_t(p)])) corners.push_back(nearest_image(map, points[std::size_t(p)], centres[i]));
      }
      if (corners.size() < 2) continue;
      const glm::dvec2 settled =
          settle_in_face(local_metric(map, lifted.triangle[i]), centres[i], corners, 0.5 * design.vertex.scale * spacing);
      if (settled != centres[i]) centres[i] = settled, moved.push_back(i);
    }
    if (!moved.empty()) {
      std::vector<glm::dvec2> again(moved.size());
      for (std::size_t k = 0; k < moved.size(); ++k) again[k] = centres[moved[k]];
      LiftedPoints relifted;
      relifted.resize(again.size());
      lift_points(map, again, relifted);
      for (std::size_t k = 0; k < moved.size(); ++k) {
        const std::size_t i = moved[k];
        lifted.triangle[i] = relifted.triangle[k];
        if (relifted.triangle[k] < 0) continue;
        lifted.position[i] = relifted.position[k];
        lifted.normal[i] = relifted.normal[k];
      }
    }
  }

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
