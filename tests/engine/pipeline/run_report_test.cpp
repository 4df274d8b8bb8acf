// Tests for engine/pipeline/run_report.cpp: count_pavement counts a hand-made pavement exactly
// (real vs virtual edges, crossing edges, elements by kind, retired particles), and on real
// pavements (bundled designs, optimizer on) its counts and report.json's agree with the pavement
// counted here element by element and edge by edge; the report carries the run's info, the surface,
// the post-processing and resolution figures and the timings with their total.
#include "pipeline/run_report.h"

#include "io/design_io.h"
#include "pipeline/pavement.h"
#include "bundled_designs.h"
#include "surface_maps.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace paver {
namespace {

const SurfaceMap& map_of(const std::string& surface) { return *test::bundled_map(surface); }

void add_element(Elements& e, ElementKind kind) {
  e.push_back(kind, 0, 0, {}, {}, {0, 0, 1}, 1, ShapeKind::Sphere);
}

TEST(CountPavement, HandMadePavement) {
  Pavement p;
  p.pattern.points.resize(5);
  p.pattern.edge_a = {0, 1, 2, 3, 4, 0};
  p.pattern.edge_b = {1, 2, 3, 4, 0, 2};
  p.pattern.edge_virtual = {0, 1, 1, 0, 0, 1};
  p.pattern.crossing_edges.resize(4);
  for (ElementKind k : {ElementKind::Vertex, ElementKind::Edge, ElementKind::Edge, ElementKind::Vertex,
                        ElementKind::Edge, ElementKind::Edge, ElementKind::Vertex})
    add_element(p.elements, k);
  p.retired = {0, 1, 0, 1, 1};

  const PavementCounts c = count_pavement(p);
  EXPECT_EQ(c.pattern_edges, 3);
  EXPECT_EQ(c.virtual_edges, 3);
  EXPECT_EQ(c.boundary_crossing_edges, 4);
  EXPECT_EQ(c.vertex_elements, 3);
  EXPECT_EQ(c.edge_elements, 4);
  EXPECT_EQ(c.retired_particles, 3);

  const PavementCounts none = count_pavement(Pavement{});
  EXPECT_EQ(none.pattern_edges + none.virtual_edges + none.boundary_crossing_edges + none.vertex_elements +
                none.edge_elements + none.retired_particles,
            0);
}

// Honeycomb on the dome with E-elements: bracing gives virtual edges, E-elements fill the boundary.
Design dome_hex_with_edge_elements() {
  Design design;
  design.pattern.tessellation = Tessellation::Hexagon;
  design.pattern.spacing = 8;
  design.elements.vertex.scale = 0.5;
  EdgeElementDesign edge;
  edge.t = 0.5, edge.scale = 0.45;
  design.elements.edge = {edge};
  return design;
}

struct Case {
  std::string name, surface;
  Design design;
};

std::vector<Case> cases() {
  const auto surfaces = test::bundled_design_surfaces(test::source_dir());
  return {{"dome_hex_with_edge_elements", "dome.obj", dome_hex_with_edge_elements()},
          {"pendant_tri_gems", surfaces.at("pendant_tri_gems.json"),
           load_design(test::source_dir() / "assets/designs/pendant_tri_gems.json")}};
}

class RunReportOnPavement : public ::testing::TestWithParam<int> {};

TEST_P(RunReportOnPavement, CountsAgreeWithThePavement) {
  const Case c = cases()[GetParam()];
  const SurfaceMap& map = map_of(c.surface);
  const Pavement p = make_pavement(map, c.design);

  // Counted here.
  long real = 0, virtual_edges = 0, vertex = 0, edge = 0, retired = 0;
  for (int e = 0; e < p.pattern.edge_count(); ++e) (p.pattern.edge_virtual[e] ? virtual_edges : real) += 1;
  for (size_t i = 0; i < p.elements.size(); ++i) (p.elements.kind[i] == ElementKind::Vertex ? vertex : edge) += 1;
  for (std::uint8_t r : p.retired) retired += r ? 1 : 0;
  ASSERT_GT(real, 0);
  ASSERT_GT(vertex, 0);
  ASSERT_GT(edge, 0) << c.name << " has E-elements";

  const PavementCounts counts = count_pavement(p);
  EXPECT_EQ(counts.pattern_edges, real);
  EXPECT_EQ(counts.virtual_edges, virtual_edges);
  EXPECT_EQ(counts.boundary_crossing_edges, long(p.pattern.crossing_edges.size()));
  EXPECT_EQ(counts.vertex_elements, vertex);
  EXPECT_EQ(counts.edge_elements, edge);
  EXPECT_EQ(counts.retired_particles, retired);
  // ... and with the quality figures of the final pavement.
  EXPECT_EQ(counts.vertex_elements, p.after.vertex_elements);
  EXPECT_EQ(counts.edge_elements, p.after.edge_elements);

  RunInfo info;
  info.surface_path = "assets/surfaces/" + c.surface;
  info.design_source = c.name;
  info.spacing_derived = false;
  StageTimings timings = p.timings;
  timings.emplace_back("export", 2.5);
  const nlohmann::json r = make_run_report(info, map, p, timings);

  EXPECT_EQ(r["pattern"]["points"].get<long>(), p.pattern.point_count());
  EXPECT_EQ(r["pattern"]["edges"].get<long>(), real);
  EXPECT_EQ(r["pattern"]["virtual_edges"].get<long>(), virtual_edges);
  EXPECT_EQ(r["pattern"]["edges"].get<long>() + r["pattern"]["virtual_edges"].get<long>(), p.pattern.edge_count());
  EXPECT_EQ(r["pattern"]["boundary_crossing_edges"].get<long>(), long(p.pattern.crossing_edges.size()));
  EXPECT_EQ(r["pattern"]["cell_edges"].get<long>(), long(p.cell.edges.size()));
  EXPECT_EQ(r["elements"]["total"].get<long>(), long(p.elements.size()));
  EXPECT_EQ(r["elements"]["vertex"].get<long>(), vertex);
  EXPECT_EQ(r["elements"]["edge"].get<long>(), edge);
  EXPECT_EQ(r["quality_after"]["elements"].get<long>(), long(p.elements.size()));
  EXPECT_EQ(r["quality_after"]["contact_violations"].get<long>(), p.after.contact_violations);
  EXPECT_EQ(r["quality_paper_method"]["contact_violations"].get<long>(), p.paper.contact_violations);
  EXPECT_EQ(r["quality_before"]["contact_violations"].get<long>(), p.before.contact_violations);
  EXPECT_EQ(r["optimization"]["retired_particles"].get<long>(), retired);
  EXPECT_EQ(r["optimization"]["iterations"].get<int>(), p.solve.iterations);
  EXPECT_EQ(r["postprocess"]["filled"].get<int>(), p.filled);
  EXPECT_EQ(r["postprocess"]["eliminated"].get<int>(), p.eliminated);
  EXPECT_EQ(r["collision_resolution"]["removed"].get<int>(), p.resolution.removed);
  EXPECT_EQ(r["collision_resolution"]["contact_springs"].get<int>(), p.resolution.contact_springs);
  EXPECT_EQ(r["collision_resolution"]["pairs_left"].get<int>(), p.resolution.pairs_left);
  // The map's energy and start in report.json's vocabulary (the summaries name them in words).
  const MapReport& mr = map.parameterization.report;
  EXPECT_EQ(r["parameterization"]["method"].get<std::string>(),
            mr.energy == MapEnergy::SymmetricDirichlet ? "symmetric_dirichlet" : "arap");
  EXPECT_EQ(r["parameterization"]["start"].get<std::string>(), mr.start_used == MapStart::Lscm ? "lscm" : "tutte");
  EXPECT_EQ(r["parameterization"]["factorizations"].get<int>(), mr.factorizations);

  EXPECT_EQ(r["surface"]["path"].get<std::string>(), info.surface_path);
  EXPECT_EQ(r["surface"]["vertices"].get<int>(), map.mesh.vertex_count());
  EXPECT_EQ(r["surface"]["faces"].get<int>(), map.mesh.face_count());
  EXPECT_EQ(r["surface"]["boundary_vertices"].get<long>(), long(map.mesh.outer_loop().size()));
  EXPECT_EQ(r["design"]["source"].get<std::string>(), c.name);
  EXPECT_EQ(r["design"]["spacing"].get<double>(), p.design.pattern.spacing);
  EXPECT_EQ(r["design"]["tessellation"].get<std::string>(), std::string(enum_name(c.design.pattern.tessellation)));
  EXPECT_FALSE(r["design"]["spacing_derived"].get<bool>());

  double total = 0;
  for (const auto& [stage, ms] : timings) {
    ASSERT_TRUE(r["timings_ms"].contains(stage)) << stage;
    EXPECT_EQ(r["timings_ms"][stage].get<double>(), ms) << stage;
    total += ms;
  }
  EXPECT_DOUBLE_EQ(r["timings_ms"]["total"].get<double>(), total);
}

INSTANTIATE_TEST_SUITE_P(Designs, RunReportOnPavement, ::testing::Values(0, 1),
                         [](const auto& info) { return cases()[info.param].name; });

TEST(RunReport, VirtualEdgesAndRetiredParticlesAreCountedOnRealPavements) {
  // The cases above exercise both counts: bracing on the honeycomb, retired particles on the pendant.
  const std::vector<Case> all = cases();
  const Pavement hex = make_pavement(map_of(all[0].surface), all[0].design);
  EXPECT_GT(count_pavement(hex).virtual_edges, 0);
  const Pavement gems = make_pavement(map_of(all[1].surface), all[1].design);
  EXPECT_GT(count_pavement(gems).retired_particles, 0);
}

}  // namespace
}  // namespace paver
