#pragma once
// A spacing D for surfaces the user gave no spacing for: about `target_points` lattice points
// over the surface (Table 1 of the paper has 550 to 1900 elements), rounded to two significant
// digits so it reads well in a design file.
#include "mesh/surface_mesh.h"
#include "pattern/unit_cell.h"

namespace paver {

double default_spacing(const SurfaceMesh& mesh, Tessellation tessellation, double target_points = 1000);

}  // namespace paver
