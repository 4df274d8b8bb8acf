// Closed surfaces (issue 12): cut across the longest axis into charts (the faces the plane crosses
// split, so that the seam is straight), mapped as an atlas, and paved as one pavement: no pair under
// the contact rule over all pairs (across the seam too), elements across the seams where the charts
// leave room, and at least 85% of the ideal count of the whole closed area (no strip forgiven along
// the seam), with no gap and with a gap of 8% of D. On the bundled bead and on the scanned bunny
// head closed at its neck.
#include "all_pairs.h"
#include "core/input_error.h"
#include "map/surface_charts.h"
#include "mesh/mesh_loader.h"
#include "pattern/default_spacing.h"
#include "pipeline/pavement.h"
#include "report/verdict.h"
#include "surface_maps.h"
#include "test_meshes.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <string>
#include <tuple>

namespace paver {
namespace {

// The scanned bunny head with its neck closed by a fan: a closed genus-0 figurine from real data.
SurfaceMesh closed_bunnyhead() {
  SurfaceMesh head = load_surface(test::scanned_mesh("bunnyhead")).mesh;
  const std::vector<int> neck = head.outer_loop();
  glm::dvec3 centre(0);
  for (const int v : neck) centre += head.positions[v];
  centre /= double(neck.size());
  std::vector<std::vector<int>> faces;
  for (const glm::ivec3& t : head.triangles) faces.push_back({t.x, t.y, t.z});
  const int c = head.vertex_count();
  head.positions.push_back(centre);
  for (std::size_t k = 0; k < neck.size(); ++k) faces.push_back({neck[(k + 1) % neck.size()], neck[k], c});
  return make_surface(head.positions, faces, "closed bunnyhead").mesh;
}

const SurfaceMap& closed_map(const std::string& name) {
  static const std::shared_ptr<const SurfaceMap> bead = test::bundled_map("bead");
  static const SurfaceMap bunny = build_surface_map(closed_bunnyhead());
  return name == "bead" ? *bead : bunny;
}

TEST(SurfaceCharts, ClosedSurfacesLoadWithNoBoundaryAndAreCutIntoCharts) {
  const SurfaceMesh bead = load_surface(test::bundled_surface("bead")).mesh;
  EXPECT_TRUE(bead.boundary_loops.empty());
  const ChartCut cut = cut_into_charts(bead, CutAxis::Auto, "bead");
  ASSERT_EQ(cut.charts.size(), 2u);
  // Across the bead's long axis (z): each half holds one pole.
  EXPECT_NEAR(std::abs(cut.normal.z), 1.0, 1e-6);
  int faces = 0;
  for (const SurfaceMesh& chart : cut.charts) {
    EXPECT_EQ(chart.boundary_loops.size(), 1u);  // a disk
    faces += chart.face_count();
  }
  // The faces the plane crosses are split, none lost.
  EXPECT_EQ(faces, cut.surface.face_count());
  EXPECT_GT(cut.surface.face_count(), bead.face_count());
  EXPECT_NEAR(surface_area(cut.surface), surface_area(bead), 1e-9 * surface_area(bead));
  // Each seam vertex appears in both charts, at the same place.
  EXPECT_EQ(cut.charts[0].boundary_loops[0].size(), cut.charts[1].boundary_loops[0].size());
  const ChartCut across_x = cut_into_charts(bead, CutAxis::X, "bead");
  EXPECT_EQ(across_x.normal, glm::dvec3(1, 0, 0));
}

// The seam is the plane's section, straight across the faces: every seam vertex lies on the plane,
// or (where a crossing would have made a sliver) no farther off it than 15% of an edge. Cut by
// whole faces, the bead's seam was a staircase half a face deep.
TEST(SurfaceCharts, TheSeamFollowsThePlaneThroughTheFaces) {
  for (const std::string name : {"bead", "bunny"}) {
    const SurfaceMesh closed = name == "bead" ? load_surface(test::bundled_surface("bead")).mesh : closed_bunnyhead();
    double longest = 0;
    for (const glm::ivec3& t : closed.triangles)
      for (int k = 0; k < 3; ++k)
        longest = std::max(longest, glm::length(closed.positions[t[k]] - closed.positions[t[(k + 1) % 3]]));
    const ChartCut cut = cut_into_charts(closed, CutAxis::Auto, name);
    int seam_vertices = 0, on_plane = 0;
    for (const SurfaceMesh& chart : cut.charts)
      for (const std::vector<int>& loop : chart.boundary_loops)
        for (const int v : loop) {
          const double off = std::abs(glm::dot(cut.normal, chart.positions[v]) - cut.offset);
          EXPECT_LE(off, 0.15 * longest) << name;
          ++seam_vertices;
          if (off < 1e-9 * longest) ++on_plane;
        }
    EXPECT_GT(seam_vertices, 20) << name;
    EXPECT_GT(on_plane, seam_vertices / 2) << name;
  }
}

TEST(SurfaceCharts, TheAtlasIsBijectiveAndKeepsTheClosedSurfacesArea) {
  for (const std::string name : {"bead", "bunny"}) {
    const SurfaceMap& map = closed_map(name);
    ASSERT_TRUE(is_atlas(map)) << name;
    EXPECT_GE(chart_count(map), 2) << name;
    EXPECT_TRUE(map.parameterization.quality.bijective()) << name;
    EXPECT_FALSE(is_band(map)) << name;
    EXPECT_FALSE(map.seamless) << name;
  }
  const SurfaceMesh bead = load_surface(test::bundled_surface("bead")).mesh;
  EXPECT_NEAR(surface_area(closed_map("bead").mesh), surface_area(bead), 1e-9 * surface_area(bead));
}

TEST(SurfaceCharts, AClosedSurfaceWithAHandleIsRefusedSayingHowToCutIt) {
  const SurfaceMesh torus = test::grid_surface(24, 12, [](double u, double v) {
    const double a = 2 * std::numbers::pi * u, b = 2 * std::numbers::pi * v;
    return glm::dvec3((3 + std::cos(b)) * std::cos(a), (3 + std::cos(b)) * std::sin(a), std::sin(b));
  });
  // grid_surface leaves the seams open; weld them into a closed torus.
  std::vector<std::vector<int>> faces;
  const auto weld = [](int i) {
    const int column = i % 25, row = i / 25;
    return (row % 12) * 24 + column % 24;
  };
  std::vector<glm::dvec3> positions(24 * 12);
  for (int i = 0; i < torus.vertex_count(); ++i) positions[weld(i)] = torus.positions[i];
  for (const glm::ivec3& t : torus.triangles) faces.push_back({weld(t.x), weld(t.y), weld(t.z)});
  try {
    make_surface(positions, faces, "torus");
    FAIL() << "a closed torus was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("1 handle"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("cut through the handles"), std::string::npos) << e.what();
  }
}

using Case = std::tuple<std::string, Tessellation>;
class ClosedSurfaces : public ::testing::TestWithParam<Case> {};

TEST_P(ClosedSurfaces, OnePavementWithNoContactAcrossTheSeamAndFillOfAtLeast85Percent) {
  const auto& [name, tessellation] = GetParam();
  const SurfaceMap& map = closed_map(name);
  for (const double gap_share : {0.0, 0.08}) {
    Design design;
    design.pattern.tessellation = tessellation;
    design.pattern.spacing = default_spacing(map.mesh, tessellation);
    design.elements.gap = gap_share * design.pattern.spacing;
    design.elements.vertex.scale = 1 - gap_share;
    const Pavement p = make_pavement(map, design);
    ASSERT_GT(p.elements.size(), 300u);
    const test::AllPairs truth = test::all_pairs(p.elements, design.elements.gap);
    EXPECT_EQ(truth.violations, 0) << "smallest clearance " << truth.min_clearance;
    EXPECT_EQ(p.after.contact_violations, truth.violations);
    EXPECT_EQ(p.after.boundary_crossings, 0);
    EXPECT_GE(p.after.fill, 0.85) << "gap " << gap_share;
    // Elements across the seams are added (refill_seams) where the charts leave room: the bead's
    // honeycomb leaves a row of them.
    if (name == "bead" && tessellation == Tessellation::Hexagon && gap_share == 0) {
      EXPECT_GE(p.refill.on_seams, 20);
    }
    if (gap_share == 0) {
      const Verdict verdict = judge_pavement(p.after);
      EXPECT_TRUE(verdict.ok) << (verdict.problems.empty() ? "" : verdict.problems.front());
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Closed, ClosedSurfaces,
                         ::testing::Combine(::testing::Values("bead", "bunny"),
                                            ::testing::Values(Tessellation::Triangle, Tessellation::Hexagon)),
                         [](const auto& info) {
                           return std::get<0>(info.param) + "_" +
                                  std::string(enum_name(std::get<1>(info.param)));
                         });

}  // namespace
}  // namespace paver
