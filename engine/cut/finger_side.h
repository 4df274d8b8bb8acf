#pragma once
// A ring at its size (issue 43): the metal of a band whose finger side is a cylinder of the
// inside diameter about the band's axis, the stones on the surface outside it. The band's
// outside may be domed or crowned; its inside is round, as a finger needs.
#include "map/surface_map.h"
#include "mesh/surface_mesh.h"

#include <glm/vec3.hpp>

#include <string>

namespace paver {

// The axis a band runs around: through the middle of its two rims' centres, along their planes'
// mean normal (Newell's, over each rim loop).
struct BandAxis {
  glm::dvec3 point{0};
  glm::dvec3 direction{0, 0, 1};  // unit
};

// How the surface lies about its axis.
struct FingerSide {
  BandAxis axis;
  double inside_radius = 0;   // surface units
  double nearest = 0;         // the surface's least distance from the axis
  double farthest = 0;        // and its greatest
  double thinnest() const { return nearest - inside_radius; }
  double thickest() const { return farthest - inside_radius; }
};

// How far p lies from the axis.
double distance_from_axis(const BandAxis& axis, const glm::dvec3& p);

// Checks that the map is a band running once around one axis, facing away from it, and at least
// `thickness` outside the cylinder of `inside_diameter` (surface units) everywhere. Throws
// InputError naming the flag (`given`: "--inside-diameter 17.3"), the figures and the fix.
FingerSide check_finger_side(const SurfaceMap& map, double inside_diameter, double thickness,
                             const std::string& given);

// The closed, outward-oriented solid between the band (its top, where the stones sit) and the
// finger side: each vertex moved along its radius onto the cylinder, the rims joined by walls.
SurfaceMesh ring_shell(const SurfaceMesh& band, const FingerSide& side);

}  // namespace paver
