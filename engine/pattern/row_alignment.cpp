#include "pattern/row_alignment.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace paver {

std::optional<RowAlignment> align_rows(const SurfaceMap& map, const UnitCell& cell, AlignAxis axis) {
  if (axis == AlignAxis::None) return RowAlignment{};
  const glm::dvec3 world(axis == AlignAxis::X, axis == AlignAxis::Y, axis == AlignAxis::Z);
  // Lines, not arrows: the doubled angle of the axis's direction on the map, summed by weight.
  double sum_cos = 0, sum_sin = 0, weight = 0, area = 0;
  const auto& mesh = map.mesh;
  for (int f = 0; f < mesh.face_count(); ++f) {
    const glm::ivec3 t = mesh.triangles[std::size_t(f)];
    const glm::dvec3 e1 = mesh.positions[std::size_t(t.y)] - mesh.positions[std::size_t(t.x)];
    const glm::dvec3 e2 = mesh.positions[std::size_t(t.z)] - mesh.positions[std::size_t(t.x)];
    const glm::dvec2 q1 = map.uv[std::size_t(t.y)] - map.uv[std::size_t(t.x)];
    const glm::dvec2 q2 = map.uv[std::size_t(t.z)] - map.uv[std::size_t(t.x)];
    const glm::dvec3 normal = glm::cross(e1, e2);
    const double twice_area = glm::length(normal);
    const double det = q1.x * q2.y - q1.y * q2.x;
    if (twice_area <= 0 || det == 0) continue;
    area += twice_area;
    // The axis in the triangle's plane, as a combination a e1 + b e2 (least squares), then the
    // same combination of the map's edges.
    const glm::dvec3 n = normal / twice_area;
    const glm::dvec3 along = world - glm::dot(world, n) * n;
    const double g11 = glm::dot(e1, e1), g12 = glm::dot(e1, e2), g22 = glm::dot(e2, e2);
    const double r1 = glm::dot(e1, along), r2 = glm::dot(e2, along);
    const double g = g11 * g22 - g12 * g12;
    if (g <= 0) continue;
    const double a = (g22 * r1 - g12 * r2) / g, b = (g11 * r2 - g12 * r1) / g;
    const glm::dvec2 on_map = a * q1 + b * q2;
    if (glm::length(on_map) == 0) continue;
    const double angle = std::atan2(on_map.y, on_map.x);
    // A triangle the axis crosses steeply says little about its direction.
    const double w = twice_area * glm::dot(along, along);
    sum_cos += w * std::cos(2 * angle);
    sum_sin += w * std::sin(2 * angle);
    weight += w;
  }
  // Under a hundredth of the area lies across the axis: nothing to follow.
  if (area <= 0 || weight < 0.01 * area) return std::nullopt;
  const double mean = 0.5 * std::atan2(sum_sin, sum_cos);
  RowAlignment out;
  out.axis = axis;
  // The doubled angles' mean resultant length R gives the circular standard deviation
  // sqrt(-2 ln R) of the doubled angle; half of it is the lines'.
  const double resultant = std::clamp(std::hypot(sum_cos, sum_sin) / weight, 1e-12, 1.0);
  out.spread_deg = 0.5 * std::sqrt(-2 * std::log(resultant)) * 180.0 / std::numbers::pi;
  // weight / area is the mean of cos^2 of the angle between the axis and the surface.
  out.axis_to_surface_deg = std::acos(std::sqrt(std::clamp(weight / area, 0.0, 1.0))) * 180.0 / std::numbers::pi;
  // The map is turned by the placement's rotation into the pattern: the axis's mean direction
  // there must be a1's.
  const double a1 = std::atan2(cell.a1.y, cell.a1.x);
  double degrees = (a1 - mean) * 180.0 / std::numbers::pi;
  // The same line either way: the rotation nearest zero.
  while (degrees > 90) degrees -= 180;
  while (degrees <= -90) degrees += 180;
  out.rotation_deg = degrees;
  return out;
}

}  // namespace paver
