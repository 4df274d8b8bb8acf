#pragma once
// Heals point defects that packing to contact leaves in the adaptive pattern's particles. Most of
// them are not the few the surface's curvature needs but bound 5-7 pairs (dislocations) frozen in
// by the packing: on the bunny head, 105 of 123 interior defects sit next to one of the opposite
// sign. A try shakes the particles around one defect (random tangent pushes), packs them to
// contact again against their fixed neighbours, and keeps the new arrangement when no pair is
// under contact (as the packing settles it) and the triangulation around it has no more defects
// than before; otherwise the patch is put back. A zero-temperature search with collective moves,
// whose even trades let a dislocation wander until it cancels (docs/topology.md).
#include "map/surface_map.h"
#include "pattern/grade_field.h"

#include <glm/vec2.hpp>

#include <atomic>
#include <vector>

namespace paver {

struct DefectHealingOptions {
  double spacing = 0;         // the largest wanted bar length; the reaches scale with it (or with contact, if larger)
  double contact = 0;         // 3D centre distance that no pair may come under (as packed)
  double margin = 0;          // 3D distance every particle keeps from the surface's boundary
  const GradeField* grade = nullptr;  // graded stones: each pair's own contact (contact_packing.h)
  double interior_depth = 0;  // particles nearer the boundary are not healed or counted (a hull's valence)
  int sweeps = 3;             // passes over the defects, one try at each
};

struct DefectHealingReport {
  int defects_before = 0, defects_after = 0;  // interior particles not 6-valent
  int tries = 0, moved = 0;                   // moved: tries whose arrangement was kept
  double milliseconds = 0;
};

// Moves `uv` (packed particles in the map); the count is unchanged. Deterministic.
DefectHealingReport heal_defects(const SurfaceMap& map, std::vector<glm::dvec2>& uv,
                                 const DefectHealingOptions& options, const std::atomic<bool>* stop = nullptr);

}  // namespace paver
