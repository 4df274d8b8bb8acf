// The whole pipeline with the section 5 optimizer, post-processing and collision resolution, on
// the bundled designs and on a real scanned surface: the figures the issue pins.
#include "io/design_io.h"
#include "elements/element_proximity.h"
#include "core/input_error.h"
#include "mesh/mesh_loader.h"
#include "pipeline/pavement.h"
#include "bundled_designs.h"
#include "surface_maps.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>

#include <map>
#include <string>

namespace paver {
namespace {

std::map<std::string, std::string> bundled_design_surfaces() { return test::bundled_design_surfaces(test::source_dir()); }

const SurfaceMap& map_of(const std::string& surface) { return *test::bundled_map(surface); }

bool is_uniform_spheres_of_diameter_d(const Design& d) {
  return d.solver.c == 0 && d.solver.m == 0 && d.elements.edge.empty() && d.elements.vertex.enabled &&
         d.elements.vertex.scale == 1;
}

class BundledDesign : public ::testing::TestWithParam<std::string> {};

TEST_P(BundledDesign, ReachesZeroCollisionsAndCrossings) {
  const auto surfaces = bundled_design_surfaces();
  const std::string name = GetParam();
  ASSERT_TRUE(surfaces.count(name)) << name << " is not in assets/designs/README.md";
  const Design design = load_design(test::source_dir() / "assets/designs" / name);
  const Pavement p = make_pavement(map_of(surfaces.at(name)), design);
  EXPECT_GT(p.after.elements, 40) << name;
  EXPECT_EQ(p.after.contact_violations, 0) << name;
  EXPECT_EQ(p.after.boundary_crossings, 0) << name;
  EXPECT_EQ(find_collisions(p.elements, p.design.elements.gap).size(), 0u) << name;
  // The optimizer, not the last-resort removal, does the work: at most 2% of elements removed.
  EXPECT_LE(p.resolution.removed, 0.02 * double(p.after.elements)) << name;
  if (is_uniform_spheres_of_diameter_d(design)) {
    EXPECT_GE(p.after.neighbor_ratio.p5, 0.99) << name;
    EXPECT_LE(p.after.neighbor_ratio.median, 1.05) << name;
  }
  // Every design starts with collisions the optimizer has to remove, or none at all.
  EXPECT_LE(p.after.contact_violations, p.before.contact_violations) << name;
}

INSTANTIATE_TEST_SUITE_P(Assets, BundledDesign, ::testing::ValuesIn([] {
                           std::vector<std::string> names;
                           for (const auto& [design, surface] : bundled_design_surfaces()) names.push_back(design);
                           return names;
                         }()),
                         [](const auto& info) {
                           std::string n = info.param.substr(0, info.param.size() - 5);
                           return n;
                         });

TEST(BundledDesigns, AllAreListed) { EXPECT_GE(bundled_design_surfaces().size(), 10u); }

// A real scanned open surface (bunnyhead, nearly closed: the hard case for the map; subdivided
// once to 12k faces) with each tessellation. How many elements the resolution removes here is
// issue 10's to fix (coverage); what must hold already is no collision and no crossing.
class ScannedSurface : public ::testing::TestWithParam<Tessellation> {
protected:
  static const SurfaceMap& bunnyhead() {
    static const SurfaceMap map =
        build_surface_map(test::subdivide(load_surface(test::scanned_mesh("bunnyhead")).mesh));
    return map;
  }
};

TEST_P(ScannedSurface, UniformPatternIsCollisionFreeAndRegular) {
  ASSERT_GE(bunnyhead().mesh.face_count(), 12000);
  Design design;
  design.pattern.tessellation = GetParam();
  design.pattern.topology = Topology::Lattice;  // the lattice and its refill; auto is tested in pavement_test
  const Pavement p = make_pavement(bunnyhead(), design);
  EXPECT_GT(p.after.elements, 300);
  EXPECT_EQ(p.after.contact_violations, 0);
  EXPECT_EQ(p.after.boundary_crossings, 0);
  EXPECT_GE(p.after.neighbor_ratio.p5, 0.99);
  // Refill packs bare regions at the design's density in a triangle packing: its spacing over D is
  // 1 for tri, 1.075 for grid, 1.225 for hex, and a fair share of the elements are refilled here.
  const double packing = std::sqrt(quality_basis(bunnyhead(), p.cell, design.elements, design.solver).area_per_element /
                                   (0.5 * std::sqrt(3.0))) / p.design.pattern.spacing;
  EXPECT_LE(p.after.neighbor_ratio.median, 1.05 * packing);
  PavementOptions no_refill;
  no_refill.refill = false;
  const Pavement bare = make_pavement(bunnyhead(), design, no_refill);
  EXPECT_GT(p.refill.added, 50);
  EXPECT_GT(p.after.fill, bare.after.fill + 0.05) << "refill must close part of the bare patches";
  EXPECT_EQ(p.after.elements, bare.after.elements + p.refill.added);
  // The initial pavement had collisions and the paper's forces alone leave some (on hex more than
  // they found); the contact springs and vacancies clear them (after: 0, above; see
  // docs/solver.md for the figures of each).
  EXPECT_GT(p.before.contact_violations, 0);
  EXPECT_GT(p.paper.contact_violations, 0);
}

INSTANTIATE_TEST_SUITE_P(Bunnyhead, ScannedSurface,
                         ::testing::Values(Tessellation::Triangle, Tessellation::Grid, Tessellation::Hexagon),
                         [](const auto& info) { return std::string(enum_name(info.param)); });

// Curvature-aware spacing (eq. 5): with m > 0 elements spread where the surface is curved, with
// m < 0 they crowd there, with m = 0 the spacing is uniform.
Pavement saddle_with_margins(double c, double m) {
  Design design;
  design.pattern.tessellation = Tessellation::Hexagon;
  design.pattern.spacing = 10;
  design.solver.c = c;
  design.solver.m = m;
  design.solver.lambda_g = 0.001;  // the paper's value for curvature-aware designs
  design.solver.iterations = 3000;  // as the bundled curvature-aware design: growing by 30-80% is slow
  return make_pavement(map_of("saddle.obj"), design);
}

TEST(CurvatureAwareSpacing, PositiveMSpreadsNegativeMCrowdsZeroIsUniform) {
  const Pavement looser = saddle_with_margins(0.3, 0.5);
  const Pavement denser = saddle_with_margins(0.3, -0.3);
  const Pavement uniform = saddle_with_margins(0.3, 0.0);
  EXPECT_GT(looser.after.spacing_curvature_spearman, 0.3);
  EXPECT_LT(denser.after.spacing_curvature_spearman, -0.3);
  EXPECT_LT(std::abs(uniform.after.spacing_curvature_spearman), 0.3);
  EXPECT_LT(uniform.after.neighbor_ratio.cv, looser.after.neighbor_ratio.cv);
  for (const Pavement* p : {&looser, &denser, &uniform}) EXPECT_EQ(p->after.contact_violations, 0);
  // The margin c = 0.3 keeps gaps between elements: nearest neighbours are >= 1.3 D apart mostly.
  EXPECT_GT(uniform.after.neighbor_ratio.median, 1.25);
}

TEST(PavementOptimization, MarginsMustNotBeNegative) {
  Design design;
  design.solver.c = 0.1;
  design.solver.m = -0.3;
  EXPECT_THROW(validate_design(design, "test"), InputError);
}

TEST(PavementOptimization, OptimizerCanBeSwitchedOffAndObserved) {
  Design design;
  design.pattern.tessellation = Tessellation::Hexagon;
  design.pattern.spacing = 6;
  PavementOptions off;
  off.optimize = false;
  const Pavement initial = make_pavement(map_of("dome.obj"), design, off);
  EXPECT_EQ(initial.solve.iterations, 0);
  EXPECT_EQ(initial.points, initial.pattern.points);

  PavementOptions observed;
  int calls = 0;
  observed.observer = [&](int iteration, const std::vector<glm::vec2>& positions) {
    ++calls;
    EXPECT_EQ(iteration, calls);
    EXPECT_EQ(positions.size(), initial.pattern.points.size());
    return iteration < 5;
  };
  const Pavement stopped = make_pavement(map_of("dome.obj"), design, observed);
  EXPECT_EQ(calls, 5);
  EXPECT_EQ(stopped.solve.iterations, 5);
  EXPECT_EQ(stopped.solve.reason, StopReason::Observer);
}

TEST(PavementOptimization, SameResultWhateverTheThreadCount) {
  Design design;
  design.pattern.tessellation = Tessellation::Triangle;
  design.pattern.spacing = 18;
  PavementOptions one, all;
  one.threads = 1;
  all.threads = 0;
  const Pavement a = make_pavement(map_of("saddle.obj"), design, one);
  const Pavement b = make_pavement(map_of("saddle.obj"), design, all);
  ASSERT_EQ(a.elements.size(), b.elements.size());
  EXPECT_EQ(a.points, b.points);
  EXPECT_EQ(a.elements.position, b.elements.position);
}

}  // namespace
}  // namespace paver

namespace paver {
namespace {

TEST(PavementOptimization, StopFlagEndsEverySolveWithoutAnObserver) {
  const SurfaceMap& map = *test::bundled_map("saddle");
  Design design;
  design.pattern.tessellation = Tessellation::Triangle;
  design.pattern.spacing = 18;
  // Asked as the optimizer starts: the pass checks the flag before each step, the solver after
  // each iteration.
  std::atomic<bool> stop = false;
  PavementOptions options;
  options.stop = &stop;
  options.on_stage = [&](const std::string& stage) {
    if (stage == "optimize") stop = true;
  };
  const Pavement p = make_pavement(map, design, options);
  EXPECT_EQ(p.solve.iterations, 1) << "the flag is checked after each iteration";
  EXPECT_EQ(p.solve.reason, StopReason::Observer);
  EXPECT_EQ(p.resolution.rounds, 0) << "no contact rounds once stopped";
}

}  // namespace
}  // namespace paver
