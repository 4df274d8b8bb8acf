#pragma once
// Proximity between elements in 3D over ALL pairs (not only pattern neighbours: a folded surface
// brings far-apart pattern points close in space), with a uniform spatial hash.
#include "elements/elements.h"

#include <vector>

namespace paver {

struct Collision {
  int i, j;          // element indices, i < j
  double distance;   // centre distance
  double overlap;    // 1 - distance / (r_i + r_j + gap): 0 = just at the required distance, 1 = same centre
  double clearance;  // distance - r_i - r_j: free space between the footprints (negative = overlap)
};

// Pairs that collide by the contact rule with `gap` (core/contact_rule.h), sorted by (i, j).
std::vector<Collision> find_collisions(const Elements& elements, double gap);

// The same pairs counted, with the worst overlap, in constant memory: what the report needs, also
// for a pile-up whose pairs would not fit in memory.
struct CollisionTally {
  long pairs = 0;
  double worst_overlap = 0;
};
CollisionTally count_collisions(const Elements& elements, double gap);

// Per element: distance to its nearest other element over (r_i + r_j) — 1 means touching;
// for equal elements it is the nearest-neighbour distance over the diameter. +inf when alone.
// With a gap, the ratio is over (r_i + r_j + gap): below 1 means the pair violates the contact rule.
std::vector<double> nearest_neighbor_ratios(const Elements& elements, double gap = 0);

// Per element: the smallest free space to any other element, distance - r_i - r_j (negative =
// overlap); exact over all pairs. +inf when alone.
std::vector<double> nearest_clearances(const Elements& elements);

// What the report measures over all pairs, in one search: the pairs that collide with `gap`
// (count_collisions), and per element the nearest-neighbour ratio over r_i + r_j without the gap
// (nearest_neighbor_ratios(elements)) and the nearest clearance (nearest_clearances).
struct ProximityFigures {
  CollisionTally collisions;
  std::vector<double> neighbor_ratios;
  std::vector<double> clearances;
};
ProximityFigures measure_proximity(const Elements& elements, double gap);

// Per V-element, its valence in space: how many V-elements lie within `shell` (> 1) times its
// nearest V-element's distance (1.25 separates the first ring from the second in triangle, square
// and hexagonal lattices alike). -1 for E-elements; 0 for a V-element whose nearest V-element lies
// farther than 1.5 times the median nearest distance (a bare patch, not a lattice site).
// The report's valence share uses it for square and hexagonal lattices (report/lattice_valence.h).
std::vector<int> vertex_valences(const Elements& elements, double shell);

}  // namespace paver
