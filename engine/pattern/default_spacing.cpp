#include "pattern/default_spacing.h"

#include "pattern/design_cell.h"

#include <cmath>

namespace paver {

double default_spacing(const SurfaceMesh& mesh, Tessellation tessellation, double target_points) {
  return default_spacing(mesh, make_unit_cell(tessellation, 1.0), target_points);
}

double default_spacing(const SurfaceMesh& mesh, const PatternDesign& pattern, double target_points) {
  PatternDesign unit = pattern;
  unit.spacing = 1;
  return default_spacing(mesh, make_base_cell(unit), target_points);
}

double default_spacing(const SurfaceMesh& mesh, const UnitCell& unit, double target_points) {
  // Points per area for D = 1 follows from the unit cell itself.
  const double points_per_area = double(unit.vertices.size()) / unit.cell_area();
  const double d = std::sqrt(surface_area(mesh) * points_per_area / target_points);
  if (!(d > 0)) return 1;
  const double magnitude = std::pow(10.0, std::floor(std::log10(d)) - 1);
  return std::round(d / magnitude) * magnitude;
}

}  // namespace paver
