#pragma once
// Particles that live in the map and move on the surface: each step is a 3D tangent displacement,
// turned into a map move by the particle's triangle, and checked against the surface (the map's
// distortion changes from triangle to triangle). The adaptive pattern's relaxation and its spring
// optimizer move their particles with it.
#include "map/boundary_index.h"
#include "map/lifting.h"
#include "map/surface_map.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <vector>

namespace paver {

struct SurfaceParticles {
  std::vector<glm::dvec2> uv;
  LiftedPoints lifted;  // uv lifted: triangle, position, normal, curvature

  int size() const { return int(uv.size()); }

  // Lifts every particle and drops those outside the map; returns the kept indices (old ones).
  std::vector<int> lift_dropping_outside(const SurfaceMap& map);

  // Moves particle i by the tangent part of step[i] (not one that is off the map). A step whose 3D result overshoots by half
  // again, or leaves the map, is halved and tried again; one that never fits is not taken.
  void step(const SurfaceMap& map, std::vector<glm::dvec3> step);

  // Pushes every particle nearer the boundary than `margin` back out to it, away from its nearest
  // boundary point (the index must reach at least `margin`).
  void keep_from_boundary(const SurfaceMap& map, const BoundaryIndex& boundary, double margin);
};

}  // namespace paver
