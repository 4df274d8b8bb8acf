#include "design_edits.h"

#include "pipeline/pavement.h"

namespace paver::studio {

Design with_tessellation(Design design, Tessellation tessellation) {
  if (design.pattern.tessellation == tessellation) return design;
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

}  // namespace paver::studio
