#pragma once
// A spacing D for surfaces the user gave no spacing for: about `target_points` lattice points
// over the surface (Table 1 of the paper has 550 to 1900 elements), rounded to two significant
// digits so it reads well in a design file.
#include "mesh/surface_mesh.h"
#include "design/design.h"
#include "pattern/unit_cell.h"

namespace paver {

double default_spacing(const SurfaceMesh& mesh, Tessellation tessellation, double target_points = 1000);
// The design's own cell: a tessellation's, or the drawn one (DesignError when it is not one).
double default_spacing(const SurfaceMesh& mesh, const PatternDesign& pattern, double target_points = 1000);
// The same for any cell at D = 1 (a drawn one: pattern/design_cell.h's make_base_cell).
double default_spacing(const SurfaceMesh& mesh, const UnitCell& unit, double target_points = 1000);

}  // namespace paver
