#pragma once
// A band's seamless map (issue 12, "Bands: seamless"; docs/holes_and_bands.md).
//
// A band (two boundary loops) mapped as an annulus puts a lattice on it that cannot close on
// itself: the rows bend around the hole. Mapped instead onto an infinite strip that repeats every
// period T, a lattice whose T is a lattice vector closes around the band with no seam.
//
// How: the annulus map's log-polar image (about the hole's patch centre, which sees the whole
// hole: angle along the band, log radius across) is a strip that wraps, each triangle in one
// piece once its corners are shifted by whole turns. ARAP is then run on it with T free: the
// global step solves for the vertices and T together, each triangle's corners shifted by their
// whole periods. Every step is shortened until no triangle folds. The result is rotated so that
// T = (period, 0) and scaled so that its area equals the surface's.
#include "map/surface_map.h"

#include <glm/vec2.hpp>

#include <optional>
#include <string>
#include <vector>

namespace paver {

struct SeamlessBandMap {
  std::vector<glm::dvec2> uv;          // #V, one copy of each vertex
  std::vector<glm::ivec3> corner_turns;  // #F: corner k of triangle t sits at uv + turns[k] * T
  double period = 0;                   // |T|; T = (period, 0)
  int iterations = 0;                  // ARAP iterations run
};

// The seamless map of a band from its annulus map (uv: #V, hole_centre as Parameterization's).
// Empty, with `why_not` set, when it cannot be made without folds.
std::optional<SeamlessBandMap> map_band_seamlessly(const SurfaceMesh& band, const std::vector<glm::dvec2>& annulus_uv,
                                                  glm::dvec2 hole_centre, std::string& why_not);

// The lifting data of a seamless map: a SurfaceMap that wraps (normals and curvature from `annulus`).
SurfaceMap make_seamless_surface_map(const SurfaceMap& annulus, const SeamlessBandMap& band);

// A band's rows close around it with one count, so their spacing along each row follows the rim's
// length: where one rim is this much shorter than the other, the surface is a sheet with a hole
// (a wall with a window), not a band, and is paved like any surface with a hole.
inline constexpr double kBandRimRatio = 0.25;

// Why a surface with two boundary loops is paved as a sheet with a hole rather than as a band
// (flat, or rims of very different lengths: above); empty when it is a band.
std::string not_a_band(const SurfaceMap& annulus);

// Both for a band's annulus map: fills annulus.seamless, or annulus.seamless_unavailable.
void add_seamless_map(SurfaceMap& annulus);

}  // namespace paver
