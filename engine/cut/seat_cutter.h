#pragma once
// The cutters of the subtractive result (paper Fig. 14, and what a setter drills): one closed
// solid per element, in the element's frame (elements/element_frame.h), that the metal loses.
//
// A jeweller's seat for a round stone (the gem's proportions, elements/element_shape.cpp) is a
// solid of revolution about the element's normal, in units of the stone's diameter d:
//   - a handle above the girdle, radius 0.5 d + 1% of d, up past the metal's top face, so that
//     the stone drops in;
//   - the girdle's band, same radius, down to just below the girdle;
//   - the seat cone, the pavilion offset by 1% of d, down to the hole's radius;
//   - a hole through (diameter 40% of d) down past the metal's bottom face, for light and
//     cleaning.
// Reaching past both faces keeps the boolean free of coplanar faces.
#include "elements/element_shape.h"
#include "elements/elements.h"
#include "mesh/surface_mesh.h"

#include <glm/vec2.hpp>

#include <vector>

namespace paver {

enum class CutterKind { Seat, Element };
PAVER_ENUM_NAMES(CutterKind, {CutterKind::Seat, "seat"}, {CutterKind::Element, "element"});

inline constexpr double kSeatClearance = 0.01;   // of d, around the girdle and the pavilion
inline constexpr double kSeatHoleRadius = 0.2;   // of d
inline constexpr int kSeatSegments = 32;         // around the axis

// The stones set `depth` deeper than the surface (their girdles that far below it, along their
// normals): what the seats are cut for, the cut files hold and the rules measure. 0: as paved.
Elements seated_stones(const Elements& stones, double depth);

// The seat's profile from top to bottom as (radius, height) in units of d, with the girdle's
// middle at height 0; `above` and `below` (units of d, > 0) are how far the handle and the hole
// reach.
std::vector<glm::dvec2> seat_profile(double above, double below);

// The closed, outward-oriented solid of revolution of `profile` with `segments` sides, capped
// at both ends, +Z its axis; unit-diameter units as the profile's.
SurfaceMesh solid_of_revolution(const std::vector<glm::dvec2>& profile, int segments);

// Volume of that polygonal solid between heights z0 < z1 (exact for the polygonal solid: each
// slab of the profile is a frustum of a regular polygon), for checks by hand.
double solid_of_revolution_volume(const std::vector<glm::dvec2>& profile, int segments, double z0, double z1);

// The cutter of element `shape` (the element itself, or the seat): its mesh in unit-diameter
// units, +Z the normal. `above`/`below` as for seat_profile (seats only).
SurfaceMesh unit_cutter(CutterKind kind, const ShapeMesh& shape, double above, double below);

}  // namespace paver
