#include "paver/surface_map.h"

#include "paver/mean_curvature.h"

#include <glm/common.hpp>

#include <algorithm>
#include <limits>

namespace paver {

SurfaceMap make_surface_map(SurfaceMesh mesh, std::vector<glm::dvec2> uv) {
  SurfaceMap map;
  map.mesh = std::move(mesh);
  map.uv = std::move(uv);
  map.normals = vertex_normals(map.mesh);
  map.curvature = mean_curvature(map.mesh);
  if (!map.curvature.empty()) {
    const auto [lo, hi] = std::minmax_element(map.curvature.begin(), map.curvature.end());
    map.curvature_min = *lo, map.curvature_max = *hi;
  }
  map.uv_min = glm::dvec2(std::numeric_limits<double>::infinity());
  map.uv_max = -map.uv_min;
  for (const auto& p : map.uv) map.uv_min = glm::min(map.uv_min, p), map.uv_max = glm::max(map.uv_max, p);
  map.grid = build_uv_grid(map.uv, map.mesh.triangles);
  return map;
}

SurfaceMap build_surface_map(SurfaceMesh mesh, const ArapOptions& options) {
  Parameterization param = parameterize_arap(mesh, options);
  std::vector<glm::dvec2> uv = param.uv;
  SurfaceMap map = make_surface_map(std::move(mesh), std::move(uv));
  map.parameterization = std::move(param);
  return map;
}

}  // namespace paver
