// A flat surface is mapped by its projection (map/planar_map.h): no distortion, rows along the
// world axis that lies most in it, and a flat sheet with one hole is not taken for a band.
#include "map/planar_map.h"
#include "map/seamless_band.h"
#include "map/surface_map.h"
#include "test_meshes.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace paver {
namespace {

// A 12 x 6 wall standing in the plane y = 3 (x along it, z up), with one 1.5 x 2 window.
SurfaceMesh wall(double bulge = 0) {
  return test::sheet_with_windows(48, 24, {{{0.437, 0.33}, {0.563, 0.67}}}, [&](double u, double v) {
    return glm::dvec3(12 * u, 3 + bulge * std::sin(3.14159 * u) * std::sin(3.14159 * v), 6 * v);
  });
}

TEST(PlanarMap, AFlatWallIsItsProjectionWithRowsAlongTheLevel) {
  const SurfaceMesh mesh = wall();
  ASSERT_EQ(mesh.boundary_loops.size(), 2u);
  const std::optional<Parameterization> flat = planar_parameterization(mesh);
  ASSERT_TRUE(flat);
  EXPECT_TRUE(flat->report.planar);
  EXPECT_TRUE(flat->quality.bijective());
  EXPECT_NEAR(flat->quality.stretch_max, 1.0, 1e-9);
  EXPECT_NEAR(flat->quality.area_distortion_mean, 0.0, 1e-9);
  // Vertices along the wall's length differ in u only, and by their 3D distance.
  const glm::dvec2 along = flat->uv[1] - flat->uv[0];
  EXPECT_NEAR(std::abs(along.x), 12.0 / 48, 1e-9);
  EXPECT_NEAR(along.y, 0.0, 1e-12);
  // The default map is this projection; one asked of a given start is not.
  const Parameterization map = parameterize_surface(mesh, map_options_for(mesh));
  EXPECT_TRUE(map.report.planar);
  EXPECT_EQ(map.uv, flat->uv);
  MapOptions lscm = map_options_for(mesh);
  lscm.start = MapStart::Lscm;
  EXPECT_FALSE(parameterize_surface(mesh, lscm).report.planar);
  EXPECT_EQ(map_method_key(map.report), "planar");
}

TEST(PlanarMap, ATiltedSheetKeepsItsWindingAndTheFirstAxisThatLiesMostInIt) {
  // The plane x + y + z = 0: x, y and z lie in it equally, so u follows x's projection.
  const glm::dvec3 e1 = glm::normalize(glm::dvec3(1, -1, 0)), e2 = glm::normalize(glm::dvec3(1, 1, -2));
  const SurfaceMesh mesh = test::grid_surface(10, 10, [&](double u, double v) { return 5 * u * e1 + 3 * v * e2; });
  const std::optional<Parameterization> flat = planar_parameterization(mesh);
  ASSERT_TRUE(flat);
  EXPECT_EQ(flat->quality.flipped_triangles, 0);
  EXPECT_NEAR(flat->quality.stretch_max, 1.0, 1e-9);
  const glm::dvec3 x_in_plane = glm::normalize(glm::dvec3(1, 0, 0) - glm::dvec3(1.0 / 3));
  const glm::dvec3 step = mesh.positions[1] - mesh.positions[0];
  EXPECT_NEAR(flat->uv[1].x - flat->uv[0].x, glm::dot(step, x_in_plane), 1e-9);
}

// A tower's face, 2 wide and 10 tall: turned a quarter, so the map is wide (rows run up it).
TEST(PlanarMap, ASurfaceTallerThanWideIsTurnedAQuarter) {
  const SurfaceMesh tower = test::grid_surface(4, 20, [](double u, double v) { return glm::dvec3(2 * u, 0, 10 * v); });
  const std::optional<Parameterization> flat = planar_parameterization(tower);
  ASSERT_TRUE(flat);
  EXPECT_EQ(flat->quality.flipped_triangles, 0) << "the winding is kept";
  const glm::dvec2 up = flat->uv[5] - flat->uv[0];  // one step up the tower
  EXPECT_NEAR(std::abs(up.x), 0.5, 1e-9);
  EXPECT_NEAR(up.y, 0.0, 1e-12);
}

TEST(PlanarMap, OnlyASurfaceFlatWithinTheToleranceIsProjected) {
  // A bulge of 1e-5 x 12 stays within kFlatTolerance of the largest extent; 1e-3 x 12 does not.
  EXPECT_TRUE(planar_parameterization(wall(1e-5 * 12)));
  EXPECT_FALSE(planar_parameterization(wall(1e-3 * 12)));
  EXPECT_FALSE(parameterize_surface(wall(1e-3 * 12), map_options_for(wall(1e-3 * 12))).report.planar);
}

// A wall with one window has two boundary loops like a ring, but rows closed around the window
// would fan out across the wall (what happened): it is paved as a sheet with a hole.
TEST(PlanarMap, AWallWithOneWindowIsNotABand) {
  const SurfaceMap flat = build_surface_map(wall());
  ASSERT_TRUE(is_band(flat));
  EXPECT_FALSE(flat.seamless);
  EXPECT_NE(flat.seamless_unavailable.find("flat"), std::string::npos) << flat.seamless_unavailable;
  // Curved, the same wall is still a sheet with a hole: its window's rim is short against its edge.
  const SurfaceMap curved = build_surface_map(wall(1.5));
  EXPECT_FALSE(curved.parameterization.report.planar);
  EXPECT_FALSE(curved.seamless);
  EXPECT_NE(curved.seamless_unavailable.find("inner rim"), std::string::npos) << curved.seamless_unavailable;
  // A ring's rims are equal: a band.
  const SurfaceMesh ring = test::band_surface(48, 6, [](double u, double v) {
    return glm::dvec3(10 * std::cos(6.28318 * u), 10 * std::sin(6.28318 * u), 4 * v);
  });
  EXPECT_EQ(not_a_band(build_surface_map(ring)), "");
}

}  // namespace
}  // namespace paver
