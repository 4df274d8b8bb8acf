// Tests for engine/solver/collision_resolution.cpp, on the pass's state as the resolution step
// gets it (pave_until) and through make_pavement on bundled designs, each
// checked with an all-pairs loop written here (a collision is a centre distance below
// r_i + r_j + gap, exactly: core/contact_rule.h): with resolution the final elements have no colliding
// pair; without it, a design the paper's method leaves colliding still collides. Contact springs
// do the work when the optimizer was stopped early, the last-resort removal takes out at most one
// element per pair, and element_anchor names the particles that carry each kind of element.
#include "solver/collision_resolution.h"

#include "io/design_io.h"
#include "pipeline/pave_once.h"
#include "pipeline/pavement.h"
#include "bundled_designs.h"
#include "surface_maps.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace paver {
namespace {

// The project's contact rule, written out, over every pair of elements.
std::vector<std::pair<int, int>> colliding_pairs(const Elements& e, double gap = 0) {
  std::vector<std::pair<int, int>> out;
  for (int i = 0; i < int(e.size()); ++i)
    for (int j = i + 1; j < int(e.size()); ++j)
      if (glm::length(e.position[i] - e.position[j]) < 0.5 * (e.diameter[i] + e.diameter[j]) + gap)
        out.emplace_back(i, j);
  return out;
}

const SurfaceMap& map_of(const std::string& surface) { return *test::bundled_map(surface); }

struct Bundled {
  Design design;
  const SurfaceMap* map;
};

Bundled bundled(const std::string& design) {
  const auto surfaces = test::bundled_design_surfaces(test::source_dir());
  EXPECT_TRUE(surfaces.count(design)) << design << " is not in assets/designs/README.md";
  return {load_design(test::source_dir() / "assets/designs" / design), &map_of(surfaces.at(design))};
}

class CollisionResolutionOnBundledDesign : public ::testing::TestWithParam<std::string> {};

TEST_P(CollisionResolutionOnBundledDesign, LeavesNoCollidingPair) {
  const Bundled b = bundled(GetParam());
  const Pavement p = make_pavement(*b.map, b.design);
  ASSERT_GT(p.elements.size(), 40u);
  const auto pairs = colliding_pairs(p.elements);
  EXPECT_TRUE(pairs.empty()) << pairs.size() << " pairs collide, the first " << pairs.front().first << " and "
                             << pairs.front().second;
  EXPECT_EQ(p.after.contact_violations, 0);
}

INSTANTIATE_TEST_SUITE_P(Assets, CollisionResolutionOnBundledDesign,
                         ::testing::Values("dome_hex_d6.json", "pendant_tri_gems.json", "saddle_tri_d18.json",
                                           "mould_grid_bosses.json"),
                         [](const auto& info) { return info.param.substr(0, info.param.size() - 5); });

// The pass's state as the resolution step gets it: the paper's optimizer and post-processing done.
PaveState before_resolution(const Bundled& b, const PavementOptions& options = {}) {
  return pave_until(map_for_topology(*b.map, Topology::Lattice), b.design, options, "resolve_collisions");
}

void resolve(const Bundled& b, PaveState& state, const PavementOptions& options = {}) {
  pave_step("resolve_collisions", map_for_topology(*b.map, Topology::Lattice), options, state);
}

TEST(CollisionResolution, WithoutItThePapersMethodLeavesCollisionsOnPendantGems) {
  // Gems on the vertices and small gems on the edges of the pendant: the paper's optimizer and
  // post-processing leave a few V-elements overlapping the E-element of an edge whose other end
  // the optimizer retired.
  const Bundled b = bundled("pendant_tri_gems.json");
  PaveState state = before_resolution(b);
  const auto pairs = colliding_pairs(state.pavement.elements);
  EXPECT_GT(pairs.size(), 0u);
  EXPECT_EQ(long(pairs.size()), state.pavement.paper.contact_violations);
  EXPECT_EQ(state.pavement.resolution.rounds, 0);

  resolve(b, state);
  const Pavement& on = state.pavement;
  EXPECT_TRUE(colliding_pairs(on.elements).empty());
  EXPECT_GT(on.resolution.rounds, 0);
  // At most one element per pair that still collides is given up.
  EXPECT_LE(on.resolution.removed, on.resolution.pairs_left);
  // Of the pairs the paper's method leaves, about as many are left after the rounds (the rounds'
  // solver iterations move the pattern: measured 4 pairs before and 5 after on this design, so
  // the bound of one more is empirical).
  EXPECT_LE(on.resolution.pairs_left, long(pairs.size()) + 1);
  // Through the whole pass (make_pavement) the same: resolution leaves no pair.
  EXPECT_EQ(make_pavement(*b.map, b.design).after.contact_violations, 0);
}

TEST(CollisionResolution, ContactSpringsSeparateWhatAShortOptimizationLeaves) {
  // The dome's hexagonal design stopped after 20 iterations still has overlapping spheres; the
  // contact springs push them apart without removing any.
  Bundled b = bundled("dome_hex_d6.json");
  b.design.solver.iterations = 20;
  PaveState state = before_resolution(b);
  const auto before = colliding_pairs(state.pavement.elements);
  ASSERT_GT(before.size(), 10u);

  resolve(b, state);
  const Pavement& on = state.pavement;
  EXPECT_TRUE(colliding_pairs(on.elements).empty());
  EXPECT_GE(on.resolution.rounds, 1);
  EXPECT_GT(on.resolution.contact_springs, 0);
  // One spring per colliding particle pair; later rounds add a few for pairs that the first
  // round's pushes brought into contact, not one per pair per round.
  EXPECT_LE(on.resolution.contact_springs, 2 * long(before.size()));
  EXPECT_GT(on.resolution.solver_iterations, 0);
  EXPECT_EQ(on.resolution.removed, 0);
}

TEST(CollisionResolution, NothingToResolveNoRounds) {
  const Bundled b = bundled("dome_hex_d6.json");
  PaveState state = before_resolution(b);
  ASSERT_EQ(state.pavement.paper.contact_violations, 0);
  resolve(b, state);
  EXPECT_EQ(state.pavement.resolution.rounds, 0);
  EXPECT_EQ(state.pavement.resolution.contact_springs, 0);
  EXPECT_EQ(state.pavement.resolution.removed, 0);
}

TEST(CollisionResolution, WithNoRoundsTheLastResortRemovesOneElementPerPair) {
  Bundled b = bundled("dome_hex_d6.json");
  b.design.solver.iterations = 20;
  PavementOptions removal_only;
  removal_only.resolution.max_rounds = 0;
  PaveState state = before_resolution(b, removal_only);
  const Elements off = state.pavement.elements;
  const auto pairs = colliding_pairs(off);
  ASSERT_GT(pairs.size(), 10u);

  resolve(b, state, removal_only);
  const Pavement& on = state.pavement;
  EXPECT_EQ(on.resolution.rounds, 0);
  EXPECT_EQ(on.resolution.contact_springs, 0);
  EXPECT_TRUE(colliding_pairs(on.elements).empty());
  EXPECT_GT(on.resolution.removed, 0);
  EXPECT_EQ(on.resolution.pairs_left, long(pairs.size())) << "no rounds: the paper's pairs are left";
  EXPECT_LE(on.resolution.removed, long(pairs.size()));
  ASSERT_EQ(on.elements.size() + size_t(on.resolution.removed), off.size());
  // What is left is the paper's elements, in order, less the removed ones.
  size_t k = 0;
  for (size_t i = 0; i < off.size() && k < on.elements.size(); ++i)
    if (off.position[i] == on.elements.position[k]) ++k;
  EXPECT_EQ(k, on.elements.size());
}

TEST(CollisionResolution, AnchorsNameTheCarryingParticles) {
  Pattern pattern;
  pattern.points = {{0, 0}, {1, 0}, {0, 1}};
  pattern.edge_a = {0, 1};
  pattern.edge_b = {1, 2};
  Pattern::CrossingEdge crossing;
  crossing.inside_point = 2;
  crossing.outside = {0, 2};
  pattern.crossing_edges = {crossing};
  ElementsDesign design;
  EdgeElementDesign first, second;
  first.t = 0.25, second.t = 0.75;
  design.edge = {first, second};

  Elements e;
  e.push_back(ElementKind::Vertex, 2, 0, {}, {}, {0, 0, 1}, 1, ShapeKind::Sphere);
  e.push_back(ElementKind::Edge, 1, 1, {}, {}, {0, 0, 1}, 1, ShapeKind::Sphere);  // edge 1 (1 -> 2), spec 1
  e.push_back(ElementKind::Edge, 0, 0, {}, {}, {0, 0, 1}, 1, ShapeKind::Sphere);  // edge 0 (0 -> 1), spec 0
  e.push_back(ElementKind::Edge, -1, 1, {}, {}, {0, 0, 1}, 1, ShapeKind::Sphere); // filling on crossing edge 0

  const ElementAnchor v = element_anchor(pattern, e, 0, design);
  EXPECT_EQ(v.a, 2);
  EXPECT_EQ(v.b, -1);
  const ElementAnchor edge1 = element_anchor(pattern, e, 1, design);
  EXPECT_EQ(edge1.a, 1);
  EXPECT_EQ(edge1.b, 2);
  EXPECT_EQ(edge1.t, 0.75);
  const ElementAnchor edge0 = element_anchor(pattern, e, 2, design);
  EXPECT_EQ(edge0.a, 0);
  EXPECT_EQ(edge0.b, 1);
  EXPECT_EQ(edge0.t, 0.25);
  const ElementAnchor filling = element_anchor(pattern, e, 3, design);
  EXPECT_EQ(filling.a, 2) << "the inside end of the crossing edge";
  EXPECT_EQ(filling.b, -1);
}

}  // namespace
}  // namespace paver
