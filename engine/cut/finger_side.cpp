#include "cut/finger_side.h"

#include "core/input_error.h"
#include "core/number_text.h"
#include "cut/thick_shell.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace paver {
namespace {

// A band faces away from its axis when its normals' mean share along the radius is at least this.
constexpr double kRadialShare = 0.5;

// Newell's normal of a closed loop (its length the loop's area, times 2) and its centre.
void loop_plane(const SurfaceMesh& mesh, const std::vector<int>& loop, glm::dvec3& normal, glm::dvec3& centre) {
  normal = glm::dvec3(0);
  centre = glm::dvec3(0);
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const glm::dvec3& a = mesh.positions[std::size_t(loop[k])];
    const glm::dvec3& b = mesh.positions[std::size_t(loop[(k + 1) % loop.size()])];
    normal += glm::cross(a, b);
    centre += a;
  }
  centre /= double(loop.size());
}

glm::dvec3 off_axis(const BandAxis& axis, const glm::dvec3& p) {
  const glm::dvec3 r = p - axis.point;
  return r - glm::dot(r, axis.direction) * axis.direction;
}

// How many times the loop turns around the axis (its angles summed).
double turns_around(const SurfaceMesh& mesh, const std::vector<int>& loop, const BandAxis& axis) {
  const glm::dvec3 u = glm::normalize(glm::cross(axis.direction, std::abs(axis.direction.x) < 0.9
                                                                        ? glm::dvec3(1, 0, 0)
                                                                        : glm::dvec3(0, 1, 0)));
  const glm::dvec3 v = glm::cross(axis.direction, u);
  double angle = 0;
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const glm::dvec3 a = off_axis(axis, mesh.positions[std::size_t(loop[k])]);
    const glm::dvec3 b = off_axis(axis, mesh.positions[std::size_t(loop[(k + 1) % loop.size()])]);
    angle += std::atan2(glm::dot(a, u) * glm::dot(b, v) - glm::dot(a, v) * glm::dot(b, u),
                        glm::dot(a, u) * glm::dot(b, u) + glm::dot(a, v) * glm::dot(b, v));
  }
  return std::abs(angle) / (2 * std::numbers::pi);
}

BandAxis band_axis(const SurfaceMesh& band) {
  glm::dvec3 n0, c0, n1, c1;
  loop_plane(band, band.boundary_loops[0], n0, c0);
  loop_plane(band, band.boundary_loops[1], n1, c1);
  if (glm::dot(n0, n1) < 0) n1 = -n1;  // a band's two rims run opposite ways
  BandAxis axis;
  axis.point = 0.5 * (c0 + c1);
  const glm::dvec3 sum = n0 + n1;
  if (glm::length(sum) > 0) axis.direction = glm::normalize(sum);
  return axis;
}

}  // namespace

double distance_from_axis(const BandAxis& axis, const glm::dvec3& p) { return glm::length(off_axis(axis, p)); }

FingerSide check_finger_side(const SurfaceMap& map, double inside_diameter, double thickness,
                             const std::string& given) {
  if (!is_band(map))
    throw InputError(given + ": a ring size is for a band (a surface with two rims, around a finger); this surface has " +
                     (is_atlas(map) ? std::string("none (it is closed)")
                                    : std::to_string(map.mesh.boundary_loops.size()) +
                                          (map.mesh.boundary_loops.size() == 1 ? " rim" : " rims")) +
                     "; leave the ring size out, or pave the band's outer face (--region)");
  FingerSide side;
  side.axis = band_axis(map.mesh);
  side.inside_radius = 0.5 * inside_diameter;
  for (const auto& loop : map.mesh.boundary_loops)
    if (std::abs(turns_around(map.mesh, loop, side.axis) - 1) > 0.25)
      throw InputError(given + ": this band's rims do not run once around one axis, so it has no finger side; leave "
                               "the ring size out and give --thickness alone");
  side.nearest = std::numeric_limits<double>::infinity();
  double facing = 0;  // the normals' share along the radius, summed: > 0 when the surface faces away from the axis
  for (std::size_t v = 0; v < map.mesh.positions.size(); ++v) {
    const glm::dvec3 radial = off_axis(side.axis, map.mesh.positions[v]);
    const double r = glm::length(radial);
    side.nearest = std::min(side.nearest, r);
    side.farthest = std::max(side.farthest, r);
    if (r > 0) facing += glm::dot(map.normals[v], radial / r);
  }
  // A flat plate with a hole has two rims around its normal too, but its normals lie along the
  // axis: a band's run out from it, mostly.
  if (std::abs(facing) < kRadialShare * double(map.mesh.positions.size()))
    throw InputError(given + ": this surface's rims run around one axis but it does not face away from it (a flat "
                             "plate with a hole?): a ring size is for a band around a finger; leave it out");
  if (!(facing > 0))
    throw InputError(given + ": this band faces its axis (it is an inside face): the stones go on the outside of a "
                             "ring; flip the surface's faces or pave its outer face");
  if (side.thinnest() <= 0)
    throw InputError(given + ": that finger side (" + significant_text(inside_diameter, 4) +
                     " across) is wider than the band, which comes within " + significant_text(side.nearest, 4) +
                     " of its axis; use an inside diameter of at most " +
                     significant_text(2 * (side.nearest - thickness), 4) + " for --thickness " + number_text(thickness));
  if (side.thinnest() < thickness)
    throw InputError(given + ": the band comes within " + significant_text(side.nearest, 4) +
                     " of its axis, which leaves " + significant_text(side.thinnest(), 3) +
                     " of metal at its thinnest, less than --thickness " + number_text(thickness) +
                     "; use an inside diameter of at most " + significant_text(2 * (side.nearest - thickness), 4) +
                     " or a thinner --thickness");
  return side;
}

SurfaceMesh ring_shell(const SurfaceMesh& band, const FingerSide& side) {
  std::vector<glm::dvec3> finger(band.positions.size());
  for (std::size_t v = 0; v < band.positions.size(); ++v) {
    const glm::dvec3 radial = off_axis(side.axis, band.positions[v]);
    finger[v] = band.positions[v] - radial + side.inside_radius * glm::normalize(radial);
  }
  return shell_between(band, finger);
}

}  // namespace paver
