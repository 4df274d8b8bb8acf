#include "surface_loader.h"

#include "test_meshes.h"

#include "mesh/mesh_loader.h"
#include "map/surface_map.h"
#include "pipeline/map_surface.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <thread>

namespace paver::studio {
namespace {

using namespace std::chrono_literals;

std::optional<SurfaceLoadOutcome> wait_for(SurfaceLoader& loader) {
  for (auto start = std::chrono::steady_clock::now(); std::chrono::steady_clock::now() - start < 120s;) {
    if (auto outcome = loader.take_outcome()) return outcome;
    std::this_thread::sleep_for(5ms);
  }
  return std::nullopt;
}

// The studio's exports equal `paver run`'s only if its map, made a few iterations at a time,
// is bit for bit the one build_surface_map makes.
TEST(SurfaceLoader, MapsExactlyAsBuildSurfaceMap) {
  for (const char* name : {"dome", "saddle"}) {
    SCOPED_TRACE(name);
    SurfaceLoader loader;
    loader.start(test::bundled_surface(name));
    const auto outcome = wait_for(loader);
    ASSERT_TRUE(outcome);
    ASSERT_TRUE(outcome->surface) << outcome->error;
    EXPECT_FALSE(loader.busy());
    const SurfaceMap& map = *outcome->surface->map;
    const SurfaceMap expected = build_surface_map(load_surface(test::bundled_surface(name)).mesh);
    EXPECT_EQ(map.uv, expected.uv);
    EXPECT_EQ(map.parameterization.report.iterations, expected.parameterization.report.iterations);
    EXPECT_EQ(map.parameterization.quality.stretch_mean, expected.parameterization.quality.stretch_mean);
    EXPECT_EQ(map.uv_min, expected.uv_min);
    EXPECT_EQ(map.uv_max, expected.uv_max);
    ASSERT_EQ(outcome->surface->timings.size(), 2u);
    EXPECT_EQ(outcome->surface->timings[0].first, "load");
    EXPECT_EQ(outcome->surface->timings[1].first, "parameterize");
  }
}

// A closed surface is cut across the axis asked for, as `paver run --cut` cuts it.
TEST(SurfaceLoader, CutsAClosedSurfaceAcrossTheAxisAskedFor) {
  SurfaceLoader loader;
  loader.start(test::bundled_surface("bead"), CutAxis::X);
  const auto outcome = wait_for(loader);
  ASSERT_TRUE(outcome && outcome->surface) << (outcome ? outcome->error : "none");
  const SurfaceMap& map = *outcome->surface->map;
  ASSERT_TRUE(is_atlas(map));
  EXPECT_EQ(map.cut_normal, glm::dvec3(1, 0, 0));
  const MappedSurface expected = map_surface_file(test::bundled_surface("bead"), {}, {}, {}, CutAxis::X);
  EXPECT_EQ(map.uv, expected.map->uv);
  // The bead's longest axis is z: the default cut is another plane.
  EXPECT_NEAR(std::abs(map_surface_file(test::bundled_surface("bead")).map->cut_normal.z), 1.0, 1e-6);
}

TEST(SurfaceLoader, ABadFileIsAnErrorNamingIt) {
  SurfaceLoader loader;
  loader.start("/nonexistent/surface.obj");
  const auto outcome = wait_for(loader);
  ASSERT_TRUE(outcome);
  EXPECT_FALSE(outcome->surface);
  EXPECT_NE(outcome->error.find("/nonexistent/surface.obj"), std::string::npos) << outcome->error;
}

TEST(SurfaceLoader, ANewLoadReplacesTheOneInProgress) {
  SurfaceLoader loader;
  loader.start(test::bundled_surface("saddle"));
  loader.start(test::bundled_surface("dome"));
  const auto outcome = wait_for(loader);
  ASSERT_TRUE(outcome && outcome->surface) << (outcome ? outcome->error : "none");
  EXPECT_EQ(outcome->surface->path, test::bundled_surface("dome"));
  EXPECT_FALSE(loader.take_outcome()) << "the abandoned load never reports";
}

}  // namespace
}  // namespace paver::studio
