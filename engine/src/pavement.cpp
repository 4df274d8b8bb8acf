#include "paver/pavement.h"

#include "paver/default_spacing.h"
#include "paver/element_placement.h"
#include "paver/input_error.h"

#include <chrono>

namespace paver {
namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

}  // namespace

UnitCell make_design_cell(const PatternDesign& pattern) {
  UnitCell cell = make_unit_cell(pattern.tessellation, pattern.spacing);
  for (size_t i = 0; i < pattern.operators.size(); ++i) {
    try {
      apply_operator(cell, pattern.operators[i]);
    } catch (const InputError& e) {
      throw InputError("pattern.operators[" + std::to_string(i) + "]: " + e.what());
    }
  }
  if (pattern.bracing) add_bracing_edges(cell);
  return cell;
}

Pavement make_pavement(const SurfaceMap& map, Design design) {
  Pavement pavement;
  auto t0 = Clock::now();
  if (design.pattern.spacing <= 0)
    design.pattern.spacing = default_spacing(map.mesh, design.pattern.tessellation);
  pavement.cell = make_design_cell(design.pattern);
  for (size_t s = 0; s < design.elements.edge.size(); ++s)
    for (int e : design.elements.edge[s].cell_edges)
      if (e < 0 || e >= int(pavement.cell.edges.size()))
        throw InputError("elements.edge[" + std::to_string(s) + "].cell_edges: edge " + std::to_string(e) +
                         " does not exist; the unit cell has edges 0.." +
                         std::to_string(pavement.cell.edges.size() - 1));
  pavement.pattern = build_pattern(map, pavement.cell, design.placement);
  pavement.points = pavement.pattern.points;
  pavement.timings.emplace_back("pattern", ms_since(t0));

  t0 = Clock::now();
  pavement.elements = place_elements(map, pavement.pattern, pavement.points, design.elements, design.pattern.spacing);
  pavement.timings.emplace_back("elements", ms_since(t0));
  pavement.design = std::move(design);
  return pavement;
}

}  // namespace paver
