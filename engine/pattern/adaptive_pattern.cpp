#include "pattern/adaptive_pattern.h"
#include "design/design_keys.h"

#include "pattern/bar_length_floor.h"
#include "pattern/pattern.h"
#include "pattern/surface_triangulation.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

namespace paver {
namespace {

constexpr double kMarginSlack = 0.01;  // x D past the element radius, so a settled spring solve keeps it

// The triangles around each vertex in cyclic order, and whether they close around it.
struct Fan {
  std::vector<int> triangles;
  bool closed = false;
};

std::vector<Fan> vertex_fans(const std::vector<glm::ivec3>& triangles, const std::vector<glm::ivec3>& neighbours,
                             int vertex_count) {
  std::vector<int> any(vertex_count, -1);
  for (int t = 0; t < int(triangles.size()); ++t)
    for (int k = 0; k < 3; ++k) any[triangles[t][k]] = t;
  const auto corner = [&](int t, int v) { return triangles[t][0] == v ? 0 : triangles[t][1] == v ? 1 : 2; };
  // Around v at corner k of (v, a, b): forward across (v, b), opposite a; backward across (v, a).
  const auto forward = [&](int t, int v) { return neighbours[t][(corner(t, v) + 1) % 3]; };
  const auto backward = [&](int t, int v) { return neighbours[t][(corner(t, v) + 2) % 3]; };
  std::vector<Fan> fans(vertex_count);
  for (int v = 0; v < vertex_count; ++v) {
    const int start = any[v];
    if (start < 0) continue;
    Fan& fan = fans[v];
    fan.triangles.push_back(start);
    // Bounded for safety: a fan has fewer triangles than the whole triangulation.
    for (int t = forward(start, v); t >= 0 && fan.triangles.size() <= triangles.size(); t = forward(t, v)) {
      if (t == start) {
        fan.closed = true;
        break;
      }
      fan.triangles.push_back(t);
    }
    if (fan.closed) continue;
    std::vector<int> back;
    for (int t = backward(start, v); t >= 0 && back.size() <= triangles.size(); t = backward(t, v)) back.push_back(t);
    fan.triangles.insert(fan.triangles.begin(), back.rbegin(), back.rend());
  }
  return fans;
}

double real_edge_length(const UnitCell& cell) {
  for (const CellEdge& e : cell.edges)
    if (!e.is_virtual) return e.rest_length;
  return cell.spacing;
}

// A regular k-gon of side `side`: the chord across `span` of its edges.
double polygon_chord(int k, int span, double side) {
  return side * std::sin(span * std::numbers::pi / k) / std::sin(std::numbers::pi / k);
}

void add_edge(Pattern& p, int a, int b, double rest, bool is_virtual) {
  p.edge_a.push_back(a);
  p.edge_b.push_back(b);
  p.edge_cell_edge.push_back(0);
  p.edge_rest_length.push_back(rest);
  p.edge_virtual.push_back(is_virtual ? 1 : 0);
}

Pattern triangle_pattern(const RelaxedParticles& relaxed, double edge_length) {
  Pattern p;
  p.points = relaxed.uv;
  p.point_cell_vertex.assign(p.points.size(), 0);
  p.point_cell.assign(p.points.size(), glm::ivec2(0));
  std::set<std::pair<int, int>> edges;
  for (const glm::ivec3& t : relaxed.triangles)
    for (int k = 0; k < 3; ++k) edges.insert(std::minmax(t[k], t[(k + 1) % 3]));
  for (const auto& [a, b] : edges) add_edge(p, a, b, edge_length, false);
  const std::vector<Fan> fans =
      vertex_fans(relaxed.triangles, triangle_neighbours(relaxed.triangles), p.point_count());
  for (int v = 0; v < p.point_count(); ++v)
    if (fans[v].closed && fans[v].triangles.size() != 6) p.defects.push_back({int(fans[v].triangles.size()), {v}});
  return p;
}

// The honeycomb dual: a point in each triangle (its map centroid), an edge across each interior
// edge, a face (and, with bracing, its long diagonals) around each interior vertex.
Pattern honeycomb_pattern(const RelaxedParticles& relaxed, double edge_length, bool bracing) {
  Pattern p;
  const auto& tris = relaxed.triangles;
  for (const glm::ivec3& t : tris)
    p.points.push_back((relaxed.uv[t.x] + relaxed.uv[t.y] + relaxed.uv[t.z]) / 3.0);
  p.point_cell_vertex.assign(p.points.size(), 0);
  p.point_cell.assign(p.points.size(), glm::ivec2(0));
  const std::vector<glm::ivec3> neighbours = triangle_neighbours(tris);
  for (int t = 0; t < int(tris.size()); ++t)
    for (int k = 0; k < 3; ++k)
      if (t < neighbours[t][k]) add_edge(p, t, neighbours[t][k], edge_length, false);
  const std::vector<Fan> fans = vertex_fans(tris, neighbours, int(relaxed.uv.size()));
  for (const Fan& fan : fans) {
    if (!fan.closed) continue;
    const int k = int(fan.triangles.size());
    if (bracing && k > 3)
      for (int i = 0; i < (k + 1) / 2; ++i)
        add_edge(p, fan.triangles[i], fan.triangles[(i + k / 2) % k], polygon_chord(k, k / 2, edge_length), true);
    if (k != 6) p.defects.push_back({k, fan.triangles});
  }
  return p;
}

}  // namespace

std::string adaptive_pattern_unsupported(const Design& design) {
  const Tessellation t = design.pattern.tessellation;
  if (t != Tessellation::Triangle && t != Tessellation::Hexagon)
    return std::string(enum_name(t)) + " has no adaptive pattern (tri and hex do)";
  if (!design.pattern.operators.empty()) return "edge operators need the lattice's directions";
  if (design.elements.face.enabled) return "F-elements sit in the lattice's faces";
  if (design.placement.scale != 1) return key_path(Key::placement_scale) + " is not 1";
  int real_edges = 0;
  for (const CellEdge& e : make_unit_cell(t, 1).edges) real_edges += !e.is_virtual;
  const auto& specs = design.elements.edge;
  for (size_t s = 0; s < specs.size(); ++s) {
    const std::string name = key_path(Key::elements_edge) + "[" + std::to_string(s) + "]";
    const std::set<int> on(specs[s].cell_edges.begin(), specs[s].cell_edges.end());
    if (!on.empty() && int(on.size()) < real_edges) return name + " sits on some edges only";
    const bool mirrored = std::abs(specs[s].t - 0.5) < 1e-12 ||
                          std::any_of(specs.begin(), specs.end(), [&](const EdgeElementDesign& o) {
                            return std::abs(o.t - (1 - specs[s].t)) < 1e-12 && o.scale == specs[s].scale &&
                                   o.shape == specs[s].shape;
                          });
    if (!mirrored) return name + " has t = " + std::to_string(specs[s].t) + " without its mirror 1 - t";
  }
  return {};
}

double particle_boundary_margin(const SurfaceMap& map, const Design& design, const GradeField* grade) {
  const double spacing = design.pattern.spacing;
  double radius = design.elements.vertex.enabled ? 0.5 * design.elements.vertex.scale * spacing : 0;
  for (const EdgeElementDesign& e : design.elements.edge) radius = std::max(radius, 0.5 * e.scale * spacing);
  // Graded towards the rims or a point (a tip at the rim): the smallest stones may lie there.
  const GradeBy by = design.elements.grade.by;
  if (grade && (by == GradeBy::Rim || by == GradeBy::Point)) radius *= grade->least_share();
  // The edge margin too: the boundary's post-processing removes every element inside it. (A closed
  // surface's charts meet at seams, not rims: their particles are kept apart across them as before.)
  return radius + (is_atlas(map) ? 0 : design.elements.margin);
}

AdaptivePattern build_adaptive_pattern(const SurfaceMap& map, const UnitCell& cell, const Design& design,
                                       const std::atomic<bool>* stop, const GradeField* grade) {
  const double spacing = design.pattern.spacing;
  const bool hex = design.pattern.tessellation == Tessellation::Hexagon;
  const double edge_length = real_edge_length(cell);
  // The particles are the pattern's vertices (tri) or its hexagons' centres (hex), a triangle
  // lattice sqrt(3) D apart; that lattice, laid out as usual, seeds them.
  const double primal = hex ? std::sqrt(3.0) * edge_length : edge_length;
  // Honeycomb vertices sit half an edge inside the particles' outer row.
  const double margin =
      std::max(0.0, particle_boundary_margin(map, design, grade) - (hex ? 0.5 * edge_length : 0)) + kMarginSlack * spacing;
  const Pattern seeds = build_pattern(map, make_unit_cell(Tessellation::Triangle, primal), design.placement);
  // Triangle particles are the elements' vertices: packed to contact before they are connected.
  // Honeycomb vertices are the triangles' centres, packed by the optimizer once they exist.
  const double contact = hex ? 0 : particle_contact_distance(design);
  const RelaxationTarget target{primal, design.solver.c, design.solver.m, margin, contact, grade};
  const RelaxedParticles relaxed = relax_particles(map, seeds.points, target, stop);
  AdaptivePattern out;
  out.relaxation = relaxed.report;
  out.pattern = hex ? honeycomb_pattern(relaxed, edge_length, design.pattern.bracing)
                    : triangle_pattern(relaxed, edge_length);
  return out;
}

}  // namespace paver
