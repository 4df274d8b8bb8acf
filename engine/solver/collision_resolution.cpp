#include "solver/collision_resolution.h"

#include "core/stopwatch.h"
#include "core/contact_rule.h"

#include "elements/element_proximity.h"
#include "map/lifting.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <map>
#include <utility>

namespace paver {
namespace {

// The particle that moves an element most directly: its own point, the nearer end of its edge.
// `avoid` (another element's particle) is skipped where the element has a second choice.
int carrier(const ElementAnchor& anchor, int avoid) {
  const int nearer = anchor.b >= 0 && anchor.t > 0.5 ? anchor.b : anchor.a;
  const int other = nearer == anchor.a ? anchor.b : anchor.a;
  return nearer == avoid && other >= 0 ? other : nearer;
}

// A pattern this large is too wide for its rows to pass their excess out to the rim within a
// round's 60 iterations (about 30 rows across a 1,000-point pattern relax in 200, docs/solver.md).
constexpr int kWidePatternParticles = 4000;

// Retires vertex elements' particles where pairs of them collide, most overlapped pair first, in
// the one of the two in more pairs; returns how many. A particle within two springs of one
// retired in this round is spared, so that vacancies stay apart and the next round sees how the
// pattern relaxed around them. Pairs with an edge element keep their contact springs' resolution
// and the final removal.
int retire_one_of_each_pair(const Pattern& pattern, const Elements& elements, std::vector<Collision> collisions,
                            const ElementsDesign& design, SpringSystem& system) {
  std::vector<int> count(elements.size(), 0);
  for (const Collision& c : collisions) ++count[c.i], ++count[c.j];
  std::sort(collisions.begin(), collisions.end(),
            [](const Collision& x, const Collision& y) { return x.overlap > y.overlap; });
  std::vector<std::uint8_t> spared(system.particle_count(), 0);
  const auto spare_around = [&](int p) {
    for (int i = system.neighbor_start[p]; i < system.neighbor_start[p + 1]; ++i) {
      const int q = system.neighbor[i];
      spared[q] = 1;
      for (int k = system.neighbor_start[q]; k < system.neighbor_start[q + 1]; ++k) spared[system.neighbor[k]] = 1;
    }
  };
  int retired = 0;
  for (const Collision& c : collisions) {
    if (elements.kind[c.i] != ElementKind::Vertex || elements.kind[c.j] != ElementKind::Vertex) continue;
    const int pi = element_anchor(pattern, elements, c.i, design).a;
    const int pj = element_anchor(pattern, elements, c.j, design).a;
    if (pi < 0 || pj < 0 || spared[pi] || spared[pj]) continue;
    if (system.stray_count[pi] == kRetired || system.stray_count[pj] == kRetired) continue;
    const bool i_pinned = system.stray_count[pi] == kPinned, j_pinned = system.stray_count[pj] == kPinned;
    if (i_pinned && j_pinned) continue;
    // A pinned particle stays where the designer put it: the other makes the vacancy.
    const int victim = i_pinned ? pj : j_pinned ? pi : count[c.j] > count[c.i] ? pj : pi;
    system.stray_count[victim] = kRetired;
    spare_around(victim);
    ++retired;
  }
  return retired;
}

}  // namespace

Removal remove_colliding(Elements& elements, double gap, std::vector<std::uint8_t>* kept) {
  Removal removal;
  for (bool first = true;; first = false) {
    const std::vector<Collision> collisions = find_collisions(elements, gap);
    if (first) removal.pairs = int(collisions.size());
    if (collisions.empty()) return removal;
    const auto is_kept = [&](int i) { return kept && (*kept)[std::size_t(i)] != 0; };
    std::vector<int> count(elements.size(), 0);
    for (const Collision& c : collisions) ++count[c.i], ++count[c.j];
    std::vector<std::uint8_t> remove(elements.size(), 0);
    std::vector<std::uint8_t> settled(elements.size(), 0);
    for (const Collision& c : collisions) {
      if (settled[c.i] || settled[c.j]) continue;
      // A face element goes before an edge element, and that before the vertex element it touches
      // (the pattern's own stones are its vertices'); else the one in more pairs.
      const auto rank = [&](int i) {
        const ElementKind k = elements.kind[std::size_t(i)];
        return k == ElementKind::Face ? 2 : k == ElementKind::Edge ? 1 : 0;
      };
      // A pinned element stays while the other of its pair can go.
      const int victim = is_kept(c.i) != is_kept(c.j) ? (is_kept(c.i) ? c.j : c.i)
                         : rank(c.i) != rank(c.j)    ? (rank(c.i) > rank(c.j) ? c.i : c.j)
                         : count[c.j] > count[c.i]   ? c.j
                                                     : c.i;
      remove[victim] = 1;
      settled[c.i] = settled[c.j] = 1;
      ++removal.removed;
      const auto v = std::size_t(victim);
      removal.places.push_back({elements.uv[v], elements.position[v], elements.diameter[v]});
    }
    elements.erase_flagged(remove);
    if (kept) {
      std::size_t out = 0;
      for (std::size_t i = 0; i < remove.size(); ++i)
        if (!remove[i]) (*kept)[out++] = (*kept)[i];
      kept->resize(out);
    }
  }
}

std::vector<std::uint8_t> pinned_vertex_elements(const Elements& elements, const SpringSystem& system) {
  std::vector<std::uint8_t> pinned(elements.size(), 0);
  for (std::size_t i = 0; i < elements.size(); ++i)
    pinned[i] = elements.kind[i] == ElementKind::Vertex && elements.source[i] >= 0 &&
                system.stray_count[std::size_t(elements.source[i])] == kPinned;
  return pinned;
}

ElementAnchor element_anchor(const Pattern& pattern, const Elements& elements, int i, const ElementsDesign& design) {
  ElementAnchor anchor;
  const int source = elements.source[i];
  if (elements.kind[i] == ElementKind::Vertex) {
    anchor.a = source;
  } else if (elements.kind[i] == ElementKind::Face) {
    anchor.a = pattern.face_corner[std::size_t(pattern.face_start[std::size_t(source)])];  // a corner carries it
  } else if (source >= 0) {
    anchor.a = pattern.edge_a[source], anchor.b = pattern.edge_b[source];
    anchor.t = design.edge[elements.spec[i]].t;
  } else {
    anchor.a = pattern.crossing_edges[-1 - source].inside_point;
  }
  return anchor;
}

Elements resolve_collisions(const SurfaceMap& map, const SolverSurface& surface, SpringSystem& system,
                            const Pattern& pattern, const ElementsDesign& spec, const SolverParams& solver_params,
                            double spacing, std::vector<glm::dvec2>& points,
                            const ElementPlacer& place, const SolverFactory& solver,
                            const CollisionResolutionOptions& options, CollisionResolutionReport& report,
                            const std::atomic<bool>* stop) {
  const Stopwatch watch;
  Elements elements = place(points, system.stray_count);
  std::map<std::pair<int, int>, int> contact_of;  // particle pair -> its contact spring
  LiftedPoints lifted;
  std::size_t previous = 0;
  // Only a wide pattern stalls (below); only a large one may end its rounds early.
  const bool wide = system.particle_count() >= kWidePatternParticles;
  const bool large = system.particle_count() >= options.large_pattern_particles;
  for (int round = 0; round < options.max_rounds; ++round) {
    // A face element's pairs are left to the removal below: its face's corners carry it, and a
    // contact spring from a corner squeezed the next face. They neither stall a round nor keep one going.
    std::vector<Collision> collisions = find_collisions(elements, spec.gap);
    std::erase_if(collisions, [&](const Collision& c) {
      return elements.kind[std::size_t(c.i)] == ElementKind::Face || elements.kind[std::size_t(c.j)] == ElementKind::Face;
    });
    if (collisions.empty() || (stop && stop->load())) break;
    // Every pattern gets one round; a large one may leave its last few pairs to the last resort.
    if (large && round > 0 &&
        double(collisions.size()) < options.large_pattern_pairs_share * double(elements.size()))
      break;
    ++report.rounds;
    // Contact springs that stopped paying: where the map leaves the lattice more particles than
    // room (rows squeezed along a line, typical of a large pattern), pushing two apart presses
    // the next pair together. A vacancy is the defect that fits there: one particle of each
    // pair that two vertex elements make is retired, and its neighbours relax into the space.
    // Only a wide pattern stalls this way: a small one can take a few rounds of more collisions
    // before its contact springs clear them all.
    const bool stalled = wide && round > 0 && double(collisions.size()) > 0.8 * double(previous);
    previous = collisions.size();
    if (stalled) {
      report.retired += retire_one_of_each_pair(pattern, elements, collisions, spec, system);
    }
    lifted.resize(points.size());
    lift_points(map, points, lifted);
    for (const Collision& c : collisions) {
      // In a stalled round, pairs of two vertex elements were given vacancies above.
      if (stalled && elements.kind[c.i] == ElementKind::Vertex && elements.kind[c.j] == ElementKind::Vertex) continue;
      const ElementAnchor ai = element_anchor(pattern, elements, c.i, spec);
      const ElementAnchor aj = element_anchor(pattern, elements, c.j, spec);
      const int pj = carrier(aj, -1);
      const int pi = carrier(ai, pj);
      if (pi < 0 || pj < 0 || pi == pj || lifted.triangle[pi] < 0 || lifted.triangle[pj] < 0) continue;
      if (system.stray_count[pi] == kRetired || system.stray_count[pj] == kRetired) continue;
      // Across an atlas's seam a spring would pull across the plane between two charts, not
      // across the surface: such a pair is left to the removal below.
      if (is_atlas(map) && map.chart_of_face[lifted.triangle[pi]] != map.chart_of_face[lifted.triangle[pj]]) continue;
      // The particles must end up as much farther apart as the elements need to.
      const double need =
          options.clearance * contact_distance(elements.diameter[c.i], elements.diameter[c.j], spec.gap);
      const double stretch = need / std::max(c.distance, 1e-9 * need);
      const double particles = glm::length(lifted.position[pi] - lifted.position[pj]);
      const float rest = float(std::max(particles * stretch, need));
      const auto key = std::minmax(pi, pj);
      const auto found = contact_of.find(key);
      if (found != contact_of.end()) {
        system.rest_length[found->second] = std::max(system.rest_length[found->second], rest);
        continue;
      }
      contact_of.emplace(key, system.spring_count());
      add_spring(system, pi, pj, rest, kSpringContact);
      ++report.contact_springs;
    }
    rebuild_neighbors(system);
    SolverParams params = solver_params;
    params.iterations = options.iterations_per_round;
    // The round's iterations all run: a pattern at rest but for a few compressed contact springs
    // moves by less than the convergence threshold per step and would stop before they act.
    params.threshold = 0;
    report.solver_iterations += solver(surface, system, params, spacing)->solve({}, stop).iterations;
    for (int i = 0; i < system.particle_count(); ++i) points[i] = glm::dvec2(system.position[i]);
    elements = place(points, system.stray_count);
  }
  // Vertex elements of pinned particles (the designer's) are the last to go.
  std::vector<std::uint8_t> pinned = pinned_vertex_elements(elements, system);
  const Removal removal = remove_colliding(elements, spec.gap, &pinned);
  report.pairs_left = removal.pairs;
  report.removed = removal.removed;
  report.removed_places = removal.places;
  report.milliseconds = watch.milliseconds();
  return elements;
}

}  // namespace paver
