#pragma once
// Particles relaxed on the surface into a near-regular triangulation whose edges have the wanted
// length, with point defects (5- and 7-valent vertices) where the surface or its map leaves no
// room for a regular lattice. DistMesh-style (Persson and Strang 2004): repulsive bars along a
// triangulation rebuilt as the particles move, with population control (Meyer et al. 2005): the
// shortest bars collapse and the longest split until the density matches. The particles live in
// the map; forces, lengths and the boundary margin are measured on the surface.
#include "map/surface_map.h"
#include "pattern/defect_healing.h"
#include "pattern/grade_field.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <atomic>
#include <vector>

namespace paver {

struct RelaxationTarget {
  double spacing = 0;         // wanted edge length on the surface where eq. 5 adds nothing
  double c = 0, m = 0;        // eq. 5: the length grows by (c + m |H|normalised) spacing
  double boundary_margin = 0; // particles stay at least this far (3D) from the surface's boundary
  double contact = 0;         // > 0: relaxed particles are then packed no nearer than this (3D)
  // Graded stones: the spacing shrinks with the grade's share, and the contact with each stone.
  const GradeField* grade = nullptr;
};

struct RelaxationReport {
  int iterations = 0;
  int inserted = 0, removed = 0;   // by population control (the seeds' thinning not counted)
  int seeds_kept = 0;              // seeds left after thinning the piled-up ones
  int packing_iterations = 0;      // contact packing after the relaxation (contact_packing.h)
  int jammed = 0;                  // particles the packing removed where no push made room
  DefectHealingReport healing;     // after the packing (defect_healing.h)
  double milliseconds = 0;
};

struct RelaxedParticles {
  std::vector<glm::dvec2> uv;             // particle positions in the map
  std::vector<glm::ivec3> triangles;      // their surface triangulation, counter-clockwise in uv
  RelaxationReport report;
};

// The wanted edge length at a point of curvature `kappa` (eq. 5's growth, as the solver's targets),
// before a grade's factor.
double relaxation_spacing(const SurfaceMap& map, const RelaxationTarget& target, double kappa);

// Relaxes `seeds` (map positions, e.g. a lattice's points) into particles at the target spacing.
// Seeds outside the map are dropped; piled-up seeds are thinned first. `stop` ends it early
// (the particles so far, triangulated).
RelaxedParticles relax_particles(const SurfaceMap& map, const std::vector<glm::dvec2>& seeds,
                                 const RelaxationTarget& target, const std::atomic<bool>* stop = nullptr);

}  // namespace paver
