#pragma once
// A surface with holes, closed into a disk for mapping (issue 12, "surfaces with holes").
//
// Each hole is closed by a temporary fan of triangles around one new vertex at the hole's
// centroid. The disk is mapped as before (bijective_map), and the patches are then dropped: a
// bijective map of the closed disk restricted to the real faces is a bijective map of the surface
// with holes, whose holes stay inside the outer loop and apart from each other because the patch
// triangles never fold. The patches are not surface: the map gives them little weight, so that
// they follow the real faces around them instead of resisting them.
#include "mesh/surface_mesh.h"

namespace paver {

// Weight in the map's energy of a patch triangle relative to a real one of the same shape.
inline constexpr double kHolePatchWeight = 1e-1;

struct PatchedSurface {
  // The surface's vertices and faces first (same indices), then one centre vertex per hole and
  // its fan; one boundary loop, the surface's outer loop.
  SurfaceMesh mesh;
  int surface_vertices = 0;
  int surface_faces = 0;
  std::vector<double> patch_hole_radius;  // per patch face: its hole's mean distance to the centre
  bool is_patch(int face) const { return face >= surface_faces; }
  double hole_radius(int face) const { return patch_hole_radius[face - surface_faces]; }
};

// The surface unchanged when it has no holes.
PatchedSurface close_holes(const SurfaceMesh& surface);

}  // namespace paver
