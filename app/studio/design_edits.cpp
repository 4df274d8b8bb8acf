#include "design_edits.h"

#include "pipeline/pavement.h"

#include <algorithm>

namespace paver::studio {

Design with_tessellation(Design design, Tessellation tessellation) {
  if (design.pattern.tessellation == tessellation) return design;
  if (tessellation == Tessellation::Custom && design.pattern.cell.vertices.empty()) {
    // A drawn cell starts as the one on screen, the operators made part of it (their virtual
    // edges too; the bracing is added anew).
    PatternDesign unbraced = design.pattern;
    unbraced.bracing = false;
    const UnitCell shown = design_cell_shape(unbraced);
    CellDesign& drawn = design.pattern.cell;
    drawn.a1 = shown.a1, drawn.a2 = shown.a2;
    for (const glm::dvec2& v : shown.vertices) drawn.vertices.push_back({v});
    for (const CellEdge& e : shown.edges) drawn.edges.push_back({e.from, e.to, e.offset, e.is_virtual});
  }
  design.pattern.tessellation = tessellation;
  design.pattern.operators.clear();
  for (EdgeElementDesign& e : design.elements.edge) e.cell_edges.clear();
  return design;
}

Design with_operator(Design design, const EdgeOperator& op) {
  design.pattern.operators.push_back(op);
  design_cell_shape(design.pattern);  // throws when the cell cannot take it
  return design;
}

Design without_operator(Design design, int index) {
  design.pattern.operators.erase(design.pattern.operators.begin() + index);
  design_cell_shape(design.pattern);
  return design;
}

UnitCell design_cell_shape(const PatternDesign& pattern) {
  PatternDesign unit = pattern;
  unit.spacing = 1;
  return make_design_cell(unit);
}

glm::dvec2 cell_view_centre(const UnitCell& cell) {
  glm::dvec2 vertices_mean(0);
  for (const glm::dvec2& v : cell.vertices) vertices_mean += v;
  vertices_mean /= double(std::max<std::size_t>(cell.vertices.size(), 1));
  return 0.5 * (vertices_mean + 0.5 * (cell.a1 + cell.a2));
}

}  // namespace paver::studio
