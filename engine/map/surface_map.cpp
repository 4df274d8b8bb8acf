#include "map/surface_map.h"

#include "map/seamless_band.h"
#include "map/surface_charts.h"
#include "mesh/mean_curvature.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace paver {

double normalised_curvature(const SurfaceMap& map, double kappa) {
  const double range = map.curvature_max - map.curvature_min;
  return range > 0 ? std::clamp((kappa - map.curvature_min) / range, 0.0, 1.0) : 0.0;
}

glm::dvec2 wrap_point(const SurfaceMap& map, glm::dvec2 p) {
  if (!map_wraps(map)) return p;
  return {p.x - map.period * std::floor((p.x - map.period_origin) / map.period), p.y};
}

glm::dvec2 nearest_image(const SurfaceMap& map, glm::dvec2 p, glm::dvec2 near) {
  if (!map_wraps(map)) return p;
  return {p.x - map.period * std::floor((p.x - near.x) / map.period + 0.5), p.y};
}

std::array<glm::dvec2, 3> triangle_uv(const SurfaceMap& map, int t) {
  if (!map_wraps(map)) {
    const glm::ivec3 c = map.mesh.triangles[t];
    return {map.uv[c.x], map.uv[c.y], map.uv[c.z]};
  }
  const glm::ivec3 c = map.domain.triangles[t];
  return {map.domain.uv[c.x], map.domain.uv[c.y], map.domain.uv[c.z]};
}

int locate_on_map(const SurfaceMap& map, glm::dvec2 p, glm::dvec3& bary) {
  if (!map_wraps(map)) return locate(map.grid, map.uv, map.mesh.triangles, p, bary);
  const int t = locate(map.grid, map.domain.uv, map.domain.triangles, wrap_point(map, p), bary);
  return t < 0 ? t : t % map.mesh.face_count();
}

void set_curvature_range(SurfaceMap& map) {
  if (map.curvature.empty()) return;
  // Percentiles, not the extremes: one sliver's huge |H| would squeeze every other vertex into
  // the bottom of the range, and c and m would act nowhere on a scanned mesh.
  std::vector<double> sorted = map.curvature;
  std::sort(sorted.begin(), sorted.end());
  const auto at = [&](double p) { return sorted[size_t(p * double(sorted.size() - 1) + 0.5)]; };
  map.curvature_min = at(kCurvatureLowPercentile), map.curvature_max = at(kCurvatureHighPercentile);
}

SurfaceMap make_surface_map(SurfaceMesh mesh, std::vector<glm::dvec2> uv) {
  SurfaceMap map;
  map.mesh = std::move(mesh);
  map.uv = std::move(uv);
  map.normals = vertex_normals(map.mesh);
  map.curvature = mean_curvature(map.mesh);
  set_curvature_range(map);
  map.uv_min = glm::dvec2(std::numeric_limits<double>::infinity());
  map.uv_max = -map.uv_min;
  for (const auto& p : map.uv) map.uv_min = glm::min(map.uv_min, p), map.uv_max = glm::max(map.uv_max, p);
  map.grid = build_uv_grid(map.uv, map.mesh.triangles);
  return map;
}

SurfaceMap make_surface_map(SurfaceMesh mesh, Parameterization parameterization) {
  const MapQuality& q = parameterization.quality;
  if (!q.bijective())
    throw std::runtime_error("the map of this surface is not bijective (" + std::to_string(q.flipped_triangles) +
                             " flipped triangles, " + std::to_string(q.boundary_intersections) +
                             " boundary crossings); please report the surface to the Paver developers");
  std::vector<glm::dvec2> uv = parameterization.uv;
  SurfaceMap map = make_surface_map(std::move(mesh), std::move(uv));
  map.parameterization = std::move(parameterization);
  add_seamless_map(map);  // a band's second map, which wraps
  return map;
}

SurfaceMap build_surface_map(SurfaceMesh mesh) {
  if (mesh.boundary_loops.empty()) return *map_closed_surface(mesh, CutAxis::Auto, "the closed surface");
  Parameterization param = parameterize_surface(mesh, map_options_for(mesh));
  return make_surface_map(std::move(mesh), std::move(param));
}

}  // namespace paver
