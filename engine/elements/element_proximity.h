#pragma once
// Proximity between elements in 3D over ALL pairs (not only pattern neighbours: a folded surface
// brings far-apart pattern points close in space), with a uniform spatial hash.
#include "elements/elements.h"

#include <vector>

namespace paver {

struct Collision {
  int i, j;          // element indices, i < j
  double distance;   // centre distance
  double overlap;    // 1 - distance / (r_i + r_j): 0 = touching, 1 = same centre
};

// Pairs that collide by the contact rule (elements/contact_rule.h), sorted by (i, j).
std::vector<Collision> find_collisions(const Elements& elements);

// Per element: distance to its nearest other element over (r_i + r_j) — 1 means touching;
// for equal elements it is the nearest-neighbour distance over the diameter. +inf when alone.
std::vector<double> nearest_neighbor_ratios(const Elements& elements);

}  // namespace paver
