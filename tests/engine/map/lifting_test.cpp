#include "map/lifting.h"
#include "map/map_quality.h"
#include "mesh/mean_curvature.h"
#include "mesh/mesh_loader.h"
#include "map/surface_map.h"
#include "surface_maps.h"
#include "test_meshes.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <random>

namespace paver {
namespace {

class LiftingOnRealMeshes : public ::testing::TestWithParam<std::string> {};

// lift(g(P)) == P: a point on the surface, mapped to the plane and lifted back, returns.
TEST_P(LiftingOnRealMeshes, RoundTripIsExact) {
  const std::string name = GetParam();
  const auto path = name == "bunnyhead" || name == "maze" ? test::scanned_mesh(name) : test::bundled_surface(name);
  const SurfaceMap map = build_surface_map(load_surface(path).mesh);
  const double scale = bounding_box_diagonal(map.mesh);

  std::mt19937 rng(42);
  std::uniform_int_distribution<int> pick(0, map.mesh.face_count() - 1);
  std::uniform_real_distribution<double> unit(0, 1);
  const int n = 5000;
  std::vector<glm::dvec3> original(n);
  std::vector<glm::dvec2> mapped(n);
  for (int i = 0; i < n; ++i) {
    const int t = pick(rng);
    double a = unit(rng), b = unit(rng);
    if (a + b > 1) a = 1 - a, b = 1 - b;
    const glm::dvec3 w(1 - a - b, a, b);
    const glm::ivec3 c = map.mesh.triangles[t];
    original[i] = w.x * map.mesh.positions[c.x] + w.y * map.mesh.positions[c.y] + w.z * map.mesh.positions[c.z];
    mapped[i] = map_point(map, t, w);
  }
  LiftedPoints lifted;
  lifted.resize(n);
  EXPECT_EQ(lift_points(map, mapped, lifted), 0);
  double worst = 0;
  for (int i = 0; i < n; ++i) {
    ASSERT_GE(lifted.triangle[i], 0);
    worst = std::max(worst, glm::length(lifted.position[i] - original[i]));
    EXPECT_NEAR(glm::length(lifted.normal[i]), 1.0, 1e-12);
  }
  EXPECT_LE(worst, 1e-9 * scale) << name;
}

INSTANTIATE_TEST_SUITE_P(Surfaces, LiftingOnRealMeshes,
                         ::testing::Values("dome", "saddle", "vase", "pendant", "bunnyhead", "maze"));

TEST(Lifting, PointsOutsideTheMapAreReported) {
  const SurfaceMap& map = *test::bundled_map("wave");
  const std::vector<glm::dvec2> points = {map.uv_max + glm::dvec2(1, 1), map.uv_min - glm::dvec2(5, 0),
                                          0.5 * (map.uv_min + map.uv_max)};
  LiftedPoints lifted;
  lifted.resize(points.size());
  EXPECT_EQ(lift_points(map, points, lifted), 2);
  EXPECT_EQ(lifted.triangle[0], -1);
  EXPECT_EQ(lifted.triangle[1], -1);
  EXPECT_GE(lifted.triangle[2], 0);
}

TEST(UvGrid, EveryTriangleCentroidIsFoundInItsTriangle) {
  const SurfaceMap map = build_surface_map(load_surface(test::scanned_mesh("bunnyhead")).mesh);
  for (int t = 0; t < map.mesh.face_count(); ++t) {
    const glm::ivec3 c = map.mesh.triangles[t];
    const glm::dvec2 centroid = (map.uv[c.x] + map.uv[c.y] + map.uv[c.z]) / 3.0;
    glm::dvec3 bary;
    ASSERT_EQ(locate(map.grid, map.uv, map.mesh.triangles, centroid, bary), t);
    EXPECT_NEAR(bary.x, 1.0 / 3, 1e-9);
  }
}

TEST(MeanCurvature, SphereCapHasCurvatureOneOverRadius) {
  // The dome is a cap of a sphere of radius 100: |H| = 1/100 away from the boundary.
  const SurfaceMesh dome = load_surface(test::bundled_surface("dome")).mesh;
  const auto h = mean_curvature(dome);
  std::vector<bool> boundary(dome.vertex_count(), false);
  for (int b : dome.outer_loop()) boundary[b] = true;
  for (int v = 0; v < dome.vertex_count(); ++v) {
    if (boundary[v]) continue;
    EXPECT_NEAR(h[v], 0.01, 0.001) << v;
  }
}

TEST(MeanCurvature, PlaneIsFlatAndNormalsAreUp) {
  const SurfaceMesh plane = test::grid_surface(6, 5, [](double u, double v) { return glm::dvec3(10 * u, 7 * v, 3); });
  for (double h : mean_curvature(plane)) EXPECT_NEAR(h, 0, 1e-12);
  for (const auto& n : vertex_normals(plane)) EXPECT_NEAR(n.z, 1, 1e-12);
}

TEST(SurfaceMap, CurvatureRangeAndBoundingBox) {
  const SurfaceMap& map = *test::bundled_map("saddle");
  EXPECT_LT(map.curvature_min, map.curvature_max);
  for (const auto& p : map.uv) {
    EXPECT_GE(p.x, map.uv_min.x);
    EXPECT_LE(p.y, map.uv_max.y);
  }
  EXPECT_TRUE(map.parameterization.quality.bijective());
}

}  // namespace
}  // namespace paver

namespace paver {
namespace {

TEST(SurfaceMap, RefusesAFoldedMap) {
  const SurfaceMesh plane = test::grid_surface(4, 4, [](double u, double v) { return glm::dvec3(u, v, 0); });
  Parameterization folded;
  for (const auto& p : plane.positions) folded.uv.emplace_back(-p.x, p.y);  // mirrored: every triangle flips
  folded.quality = measure_map(plane, folded.uv);
  ASSERT_GT(folded.quality.flipped_triangles, 0);
  try {
    make_surface_map(plane, folded);
    FAIL() << "a folded map was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("not bijective"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace paver
