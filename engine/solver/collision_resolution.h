#pragma once
// Beyond the paper: no collision left. The paper's forces act on pattern springs only, so two
// elements can still overlap: across a spring that stayed compressed, near the boundary where
// strays are pulled back, or far apart in the pattern but near in space on a folded surface.
// Each round finds every colliding pair in 3D (all pairs, spatial hash), adds a contact spring
// between the particles that carry the two elements (rest length = the distance they need),
// and runs more solver iterations, so the pattern itself makes room. Where those springs stall
// in a wide pattern, the rounds retire particles instead, one per colliding pair and apart from
// each other (vacancies the neighbours relax into). What still collides after the last round is
// removed, one element per pair, and counted.
#include "design/design.h"
#include "elements/elements.h"
#include "pattern/pattern.h"
#include "solver/solver_surface.h"
#include "solver/spring_solver.h"
#include "solver/spring_system.h"
#include "map/surface_map.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <vector>

namespace paver {

struct CollisionResolutionOptions {
  int max_rounds = 8;              // detect + relax rounds
  int iterations_per_round = 60;   // solver iterations after each round of new contact springs
  double clearance = 1.01;         // contact rest length = clearance * (r_i + r_j + gap): aims past the rule
  // After its first round, a large pattern ends its rounds once it has fewer colliding pairs than
  // this share of its elements; the last resort removes at most one element per pair left. A
  // round costs seconds there and the last ones clear few pairs (lily at 1M points: three rounds
  // of about 4.5 s for 0.1% of fill, docs/solver.md).
  int large_pattern_particles = 200000;
  double large_pattern_pairs_share = 0.01;
};

// Where an element was taken away: the studio draws a ghost there (a hole the eye can find).
struct RemovedElement {
  glm::dvec2 uv{0};
  glm::dvec3 position{0};
  double diameter = 0;
};

struct CollisionResolutionReport {
  int rounds = 0;
  int contact_springs = 0;
  int solver_iterations = 0;
  int retired = 0;                 // particles retired where contact springs stalled (vacancies)
  int pairs_left = 0;              // pairs that still collided after the last round
  int removed = 0;                 // elements removed because they still collided (one per pair at most)
  std::vector<RemovedElement> removed_places;  // where those were, #removed
  double milliseconds = 0;
};

// The particle(s) an element is attached to: its point (V), the ends of its edge (E), or the
// inside end of its crossing edge (filling).
struct ElementAnchor {
  int a = -1, b = -1;
  double t = 0;                    // position between a and b (0 for V)
};
ElementAnchor element_anchor(const Pattern& pattern, const Elements& elements, int i, const ElementsDesign& design);

// Places the elements on `points` (post-processing included), skipping retired particles.
using ElementPlacer =
    std::function<Elements(const std::vector<glm::dvec2>& points, const std::vector<std::uint32_t>& stray_count)>;

// The last resort: removes one element of every pair that still collides (a face element before an
// edge element, and that before the vertex element it touches, else the one in more pairs) until none does. Elements flagged in
// `kept` (#elements, the designer's pinned ones) go only when both of a pair are flagged; the flags
// are erased along with their elements.
struct Removal {
  int pairs = 0;    // pairs that collided before any removal
  int removed = 0;  // elements removed: at most one per pair
  std::vector<RemovedElement> places;  // where each was
};
Removal remove_colliding(Elements& elements, double gap, std::vector<std::uint8_t>* kept = nullptr);

// #elements: 1 for the vertex elements of pinned particles (the designer's), which remove_colliding
// takes last.
std::vector<std::uint8_t> pinned_vertex_elements(const Elements& elements, const SpringSystem& system);

// Inputs: the map and its solver form, the solved spring system and pattern with their particle
// positions `points` (#P), the design's elements (gap, E-element positions), solver parameters and
// spacing D, how elements are placed on particles. Output: the final elements, no pair colliding
// but those the last resort removed (`report` says how many); `system` and `points` are updated
// in place.
Elements resolve_collisions(const SurfaceMap& map, const SolverSurface& surface, SpringSystem& system,
                            const Pattern& pattern, const ElementsDesign& spec, const SolverParams& solver_params,
                            double spacing, std::vector<glm::dvec2>& points,
                            const ElementPlacer& place, const SolverFactory& solver,
                            const CollisionResolutionOptions& options, CollisionResolutionReport& report,
                            const std::atomic<bool>* stop = nullptr);

}  // namespace paver
