#include "pattern/design_cell.h"

#include "core/input_error.h"
#include "design/design_keys.h"
#include "pattern/adaptive_pattern.h"
#include "pattern/design_overlap.h"

#include <string>

namespace paver {

UnitCell make_base_cell(const PatternDesign& pattern) {
  if (pattern.tessellation != Tessellation::Custom) return make_unit_cell(pattern.tessellation, pattern.spacing);
  try {
    return make_drawn_cell(pattern.cell, pattern.spacing);
  } catch (const InputError& e) {
    const std::string_view a1 = design_key(Key::cell_a1).path;  // "pattern.cell.a1"
    throw DesignError(std::string(a1.substr(0, a1.rfind('.'))) + ": " + e.what());
  }
}

UnitCell make_design_cell(const PatternDesign& pattern) {
  UnitCell cell = make_base_cell(pattern);
  for (size_t i = 0; i < pattern.operators.size(); ++i) {
    try {
      apply_operator(cell, pattern.operators[i]);
    } catch (const InputError& e) {
      throw DesignError(key_path(Key::pattern_operators) + "[" + std::to_string(i) + "]: " + e.what());
    }
  }
  if (pattern.bracing) add_bracing_edges(cell);
  return cell;
}

void check_edits_topology(const Design& design) {
  const Topology topology = design.pattern.topology;
  const std::string topology_key = key_path(Key::pattern_topology);
  if (!design.guidance.empty() && topology == Topology::Adaptive)
    throw DesignError(key_path(Key::guidance) + ": the adaptive pattern cannot follow a guidance field yet; use " +
                      topology_key + " \"lattice\" (or \"auto\", which keeps the lattice when a field is painted)");
  const ElementEdits& edits = design.edits;
  if (edits.empty()) return;
  if (topology == Topology::Auto)
    throw DesignError("edits: element edits name the elements of one pattern, but " + topology_key +
                      " is \"auto\"; set it to \"lattice\" or \"adaptive\" (the one the edits were made on)");
  if (topology == Topology::Adaptive && !(edits.moved.empty() && edits.added.empty()))
    throw DesignError(key_path(edits.moved.empty() ? Key::edits_added : Key::edits_moved) +
                      ": the adaptive pattern's relaxation cannot hold elements in place yet; use " + topology_key +
                      " \"lattice\" to pin, move or add elements (deleting works on both)");
}

UnitCell check_design_cell(const Design& design) {
  check_edits_topology(design);
  // The checks run on the cell at D = 1: they are scale-free, and a spacing far from the surface's
  // size (or still 0, to be derived) must not make lengths underflow into false overlaps.
  PatternDesign unit = design.pattern;
  unit.spacing = 1;
  const UnitCell unit_cell = make_design_cell(unit);
  for (size_t s = 0; s < design.elements.edge.size(); ++s)
    for (int e : design.elements.edge[s].cell_edges)
      if (e < 0 || e >= int(unit_cell.edges.size()))
        throw DesignError(key_path(Key::edge_cell_edges, s) + ": edge " + std::to_string(e) +
                          " does not exist; the unit cell has edges 0.." + std::to_string(unit_cell.edges.size() - 1));
  if (!design.elements.allow_overlap) check_design_overlaps(unit_cell, design.elements, 1.0);
  if (design.pattern.topology == Topology::Adaptive)
    if (const std::string why = adaptive_pattern_unsupported(design); !why.empty())
      throw DesignError(key_path(Key::pattern_topology) + ": \"adaptive\" cannot take this design: " + why +
                        "; use \"lattice\"");
  if (design.pattern.spacing <= 0) return unit_cell;
  UnitCell cell = design.pattern.spacing != 1 ? make_design_cell(design.pattern) : unit_cell;
  // The gap is in surface units: it is checked at the real spacing, once that is known.
  if (!design.elements.allow_overlap && design.elements.gap > 0)
    check_design_overlaps(cell, design.elements, design.pattern.spacing, design.elements.gap);
  return cell;
}

}  // namespace paver
