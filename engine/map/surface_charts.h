#pragma once
// Closed surfaces (issue 12, "Closed surfaces"; docs/holes_and_bands.md): a bead or a figurine has
// no boundary, so no single map of it is bijective. It is cut by a plane across its longest axis
// into charts (the faces on each side, each connected piece a chart: a disk, or a disk with holes
// where the plane cuts it more than once), each chart is mapped as an open surface, and the maps
// are laid side by side in one plane: an atlas. The pipeline paves the atlas like any map; the
// charts' boundaries are seams, not rims: elements keep half the gap off them, so that two elements
// facing each other across a seam keep the whole gap, and any pair that still collides across a
// seam is left to the last resort (removal), since a spring between two charts would pull across
// the atlas, not the surface.
#include "design/cut_axis.h"
#include "map/surface_map.h"

#include <glm/vec3.hpp>

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace paver {

// The plane's normal (design/cut_axis.h): the surface's longest axis (principal axis of its area), or a given one.

struct ChartCut {
  SurfaceMesh surface;                      // the closed surface, its faces split along the plane
  std::vector<SurfaceMesh> charts;          // each open, its loops the seams
  std::vector<std::vector<int>> vertex_of;  // per chart: chart vertex -> `surface` vertex
  glm::dvec3 normal{0, 0, 1};               // the cutting plane: dot(normal, p) = offset
  double offset = 0;
};

// Cuts a closed surface (no boundary loop) through its area centroid, splitting the faces the plane
// crosses so that the seams are straight, not stepped by whole faces. Automatically: across its
// longest axis, or, when it has handles (a solid ring), across the first of its shortest, middle
// and longest axes that leaves charts without handles (a ring lying flat: its upper and lower
// halves, two bands). Throws InputError, naming `source`, when a chart is not a surface Paver maps
// (it has handles).
ChartCut cut_into_charts(const SurfaceMesh& closed, CutAxis axis, const std::string& source);

// The handles of a closed, connected, oriented surface: V - E + F = 2 - 2 * handles, E = 3F / 2;
// from its counts (an atlas keeps those of the surface it was cut from).
long long closed_surface_handles(long long vertices, long long faces);
long long closed_surface_handles(const SurfaceMesh& closed);

// Whether cutting across `axis` leaves charts Paver maps (always, for a surface without handles).
bool cuts_into_charts(const SurfaceMesh& closed, CutAxis axis);

// Maps each chart (bijective ARAP, as an open surface) and lays them out: the atlas. `progress`
// gets (chart, charts) before each; `stop` is polled between charts. Empty when stopped.
std::optional<SurfaceMap> map_closed_surface(const SurfaceMesh& closed, CutAxis axis, const std::string& source,
                                             const std::function<void(int chart, int charts)>& progress = {},
                                             const std::function<bool()>& stop = {});

}  // namespace paver
