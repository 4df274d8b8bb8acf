#include "pattern/bar_length_floor.h"

#include "core/contact_rule.h"
#include "pattern/design_cell.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace paver {

double bar_length_floor(const Design& design) {
  const double spacing = design.pattern.spacing, gap = design.elements.gap;
  // Elements met walking out from a vertex along a bar: where (x bar length) and how wide.
  struct OnBar {
    double s, diameter;
  };
  std::vector<OnBar> along;
  const double vertex = design.elements.vertex.enabled ? design.elements.vertex.scale * spacing : 0;
  for (const EdgeElementDesign& e : design.elements.edge) along.push_back({e.t, e.scale * spacing});
  if (vertex > 0) along.push_back({1, vertex});
  // The narrowest turn between two bars at a vertex: the paper's three keep their 60 and 120
  // degrees (a grid's too, as it always was); the others are measured on their cell.
  const Tessellation t = design.pattern.tessellation;
  const double angle = t == Tessellation::Hexagon ? 2 * std::numbers::pi / 3
                       : t == Tessellation::Triangle || t == Tessellation::Grid
                           ? std::numbers::pi / 3
                           : [&] {
                               PatternDesign unit = design.pattern;
                               unit.spacing = 1;  // the angle is scale-free, and D may still be 0
                               return smallest_edge_angle(make_base_cell(unit));
                             }();
  double floor = 0;
  const auto need = [&](double apart, double da, double db) {
    if (apart > 1e-12) floor = std::max(floor, contact_distance(da, db, gap) / apart);
  };
  for (const OnBar& a : along) {
    if (vertex > 0) need(a.s, vertex, a.diameter);  // the shared vertex's element
    for (const OnBar& b : along) {
      need(std::abs(a.s - b.s), a.diameter, b.diameter);  // on the same bar
      need(std::sqrt(a.s * a.s + b.s * b.s - 2 * a.s * b.s * std::cos(angle)), a.diameter, b.diameter);  // beside
    }
  }
  return floor;
}

double particle_contact_distance(const Design& design) {
  const ElementsDesign& e = design.elements;
  const double vertex = e.vertex.enabled ? e.vertex.scale * design.pattern.spacing : 0;
  const double vertices = vertex > 0 ? contact_distance(vertex, vertex, e.gap) : 0;
  return std::max(vertices, bar_length_floor(design)) * (1 + 2 * kContactAim);
}

}  // namespace paver
