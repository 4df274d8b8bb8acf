#include "mesh/surface_scaling.h"

#include "mesh/triangle_geometry.h"

#include <cmath>

namespace paver::detail {

double uv_area(const SurfaceMesh& mesh, const std::vector<glm::dvec2>& uv) {
  double area = 0;
  for (const auto& t : mesh.triangles) area += signed_area(uv[t.x], uv[t.y], uv[t.z]);
  return area;
}

UvRescale scale_to_surface_area(const SurfaceMesh& mesh, std::vector<glm::dvec2>& uv) {
  const double a2 = std::abs(uv_area(mesh, uv));
  if (!(a2 > 0)) return {};
  const double s = std::sqrt(surface_area(mesh) / a2);
  glm::dvec2 centre(0);
  for (const auto& p : uv) centre += p;
  centre /= double(uv.size());
  // Centring too keeps coordinates small, which keeps float32 lifting accurate.
  const UvRescale rescale{centre, s};
  for (auto& p : uv) p = rescale(p);
  return rescale;
}

}  // namespace paver::detail
