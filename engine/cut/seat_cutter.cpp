#include "cut/seat_cutter.h"


#include <cmath>
#include <numbers>

namespace paver {

std::vector<glm::dvec2> seat_profile(double above, double below) {
  const double girdle_radius = 0.5 + kSeatClearance;
  const double girdle_bottom = -kGemGirdleHalf - kSeatClearance;
  // The pavilion's radius falls from 0.5 at the girdle to 0 at the culet; the seat cone keeps
  // kSeatClearance outside it, down to the hole's radius.
  const double culet = -kGemGirdleHalf - kGemPavilionDepth;
  const double cone_end = culet + kGemPavilionDepth * (kSeatHoleRadius - kSeatClearance) / 0.5;
  return {{girdle_radius, above},
          {girdle_radius, girdle_bottom},
          {kSeatHoleRadius, cone_end},
          {kSeatHoleRadius, -below}};
}

SurfaceMesh solid_of_revolution(const std::vector<glm::dvec2>& profile, int segments) {
  SurfaceMesh m;
  const int rings = static_cast<int>(profile.size());
  for (const glm::dvec2& p : profile)
    for (int s = 0; s < segments; ++s) {
      const double a = 2 * std::numbers::pi * s / segments;
      m.positions.emplace_back(p.x * std::cos(a), p.x * std::sin(a), p.y);
    }
  const int top = static_cast<int>(m.positions.size());
  m.positions.emplace_back(0, 0, profile.front().y);
  const int bottom = top + 1;
  m.positions.emplace_back(0, 0, profile.back().y);
  const auto at = [&](int ring, int s) { return ring * segments + (s % segments); };
  for (int s = 0; s < segments; ++s) {
    m.triangles.emplace_back(top, at(0, s), at(0, s + 1));  // counter-clockwise seen from above
    for (int r = 0; r + 1 < rings; ++r) {  // the side, facing out as the profile runs downwards
      m.triangles.emplace_back(at(r, s), at(r + 1, s), at(r + 1, s + 1));
      m.triangles.emplace_back(at(r, s), at(r + 1, s + 1), at(r, s + 1));
    }
    m.triangles.emplace_back(bottom, at(rings - 1, s + 1), at(rings - 1, s));
  }
  return m;
}

double solid_of_revolution_volume(const std::vector<glm::dvec2>& profile, int segments, double z0, double z1) {
  // A regular n-gon of circumradius r has area n/2 r^2 sin(2 pi / n); between two profile points
  // the radius is linear in z, so each slab is a prismatoid: h/6 (A0 + 4 Amid + A1).
  const double k = 0.5 * segments * std::sin(2 * std::numbers::pi / segments);
  double volume = 0;
  for (std::size_t i = 0; i + 1 < profile.size(); ++i) {
    const glm::dvec2 upper = profile[i], lower = profile[i + 1];
    const double lo = std::max(z0, lower.y), hi = std::min(z1, upper.y);
    if (!(hi > lo)) continue;
    const auto radius = [&](double z) {
      return upper.y == lower.y ? upper.x : lower.x + (upper.x - lower.x) * (z - lower.y) / (upper.y - lower.y);
    };
    const double r0 = radius(lo), r1 = radius(hi), rm = radius(0.5 * (lo + hi));
    volume += (hi - lo) / 6 * k * (r0 * r0 + 4 * rm * rm + r1 * r1);
  }
  return volume;
}

SurfaceMesh unit_cutter(CutterKind kind, const ShapeMesh& shape, double above, double below) {
  if (kind == CutterKind::Seat) return solid_of_revolution(seat_profile(above, below), kSeatSegments);
  SurfaceMesh m;
  for (const glm::vec3& p : shape.positions) m.positions.emplace_back(p);
  m.triangles = shape.triangles;
  return m;
}

Elements seated_stones(const Elements& stones, double depth) {
  Elements seated = stones;
  for (std::size_t i = 0; i < seated.size(); ++i) seated.position[i] -= depth * seated.normal[i];
  return seated;
}

}  // namespace paver
