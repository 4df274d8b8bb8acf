#pragma once
// The adaptive pattern's optimizer. The paper's springs move particles in the map by 2D lengths
// scaled per spring (l_ab = L_ab |p_a p_b| / |P_a P_b|); on a map as sheared as a flattened head
// that collapses pairs and tears springs (measured in docs/topology.md). Here every force and
// length is on the surface: springs pull each pattern edge to its eq. 5 target, contact pushes
// every pair of V-elements apart to the contact rule with the gap, and particles keep an element
// radius from the boundary. Contact is part of the relaxation, so no separate resolution runs.
#include "design/design.h"
#include "map/surface_map.h"
#include "pattern/grade_field.h"
#include "pattern/pattern.h"
#include "solver/solver_backend.h"

#include <glm/vec2.hpp>

#include <atomic>
#include <vector>

namespace paver {

struct SurfaceSpringOptions {
  int iterations = 600;
  double step = 0.2;          // of the force (a spring's full correction is 1)
  double max_move = 0.1;      // x D per iteration
  double settled = 1e-4;      // x D: the largest move once converged
  int packing_iterations = 1500;  // the contact packing that ends it (contact_packing.h)
  const GradeField* grade = nullptr;  // graded stones: the design's field (pattern/grade_field.h)
};

// Relaxes `points` (the pattern's particles, in the map) in place.
SolveReport relax_pattern_on_surface(const SurfaceMap& map, const Pattern& pattern, std::vector<glm::dvec2>& points,
                                     const Design& design, const SurfaceSpringOptions& options = {},
                                     const std::atomic<bool>* stop = nullptr);

}  // namespace paver
