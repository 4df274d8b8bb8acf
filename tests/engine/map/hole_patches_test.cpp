// Surfaces with holes are mapped as disks whose holes are closed by temporary patches: the patches
// make one disk, and the map of the surface that is left is bijective with every hole inside the
// outer loop, turned the other way, and apart from the other holes.
#include "map/hole_patches.h"
#include "map/surface_map.h"
#include "map_polygon.h"
#include "mesh/mesh_loader.h"
#include "surface_maps.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>
#include <utility>

namespace paver {
namespace {

// Every directed side used once, and V - E + F = 1 with one boundary loop: a disk.
void expect_disk(const SurfaceMesh& mesh) {
  std::set<std::pair<int, int>> sides;
  for (const glm::ivec3& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) EXPECT_TRUE(sides.insert({t[k], t[(k + 1) % 3]}).second) << "side used twice";
  std::set<std::pair<int, int>> edges;
  for (const auto& [a, b] : sides) edges.insert({std::min(a, b), std::max(a, b)});
  EXPECT_EQ(long(mesh.vertex_count()) - long(edges.size()) + long(mesh.face_count()), 1);
  long boundary = 0;
  for (const auto& [a, b] : sides) boundary += !sides.count({b, a});
  EXPECT_EQ(boundary, long(mesh.outer_loop().size())) << "only the outer loop is left open";
}

TEST(HolePatches, CloseEveryHoleIntoOneDiskAndKeepTheSurfaceFirst) {
  for (const char* name : {"pendant_pierced", "facade_windows"}) {
    SCOPED_TRACE(name);
    const SurfaceMesh surface = load_surface(test::bundled_surface(name)).mesh;
    ASSERT_GT(surface.hole_count(), 2);
    const PatchedSurface patched = close_holes(surface);
    EXPECT_EQ(patched.surface_vertices, surface.vertex_count());
    EXPECT_EQ(patched.surface_faces, surface.face_count());
    EXPECT_EQ(patched.mesh.vertex_count(), surface.vertex_count() + surface.hole_count());
    for (int f = 0; f < surface.face_count(); ++f) ASSERT_EQ(patched.mesh.triangles[f], surface.triangles[f]);
    ASSERT_EQ(patched.mesh.boundary_loops.size(), 1u);
    EXPECT_EQ(patched.mesh.outer_loop(), surface.outer_loop());
    expect_disk(patched.mesh);
  }
}

TEST(HolePatches, ADiskIsLeftAsItIs) {
  const SurfaceMesh surface = load_surface(test::bundled_surface("pendant")).mesh;
  const PatchedSurface patched = close_holes(surface);
  EXPECT_EQ(patched.mesh.face_count(), surface.face_count());
  EXPECT_EQ(patched.mesh.boundary_loops, surface.boundary_loops);
}

class HoledMap : public ::testing::TestWithParam<std::string> {};

TEST_P(HoledMap, IsBijectiveWithEachHoleInsideTheOuterLoopTurnedTheOtherWayAndApart) {
  const auto map = test::named_map(GetParam());
  const SurfaceMesh& mesh = map->mesh;
  ASSERT_GE(mesh.boundary_loops.size(), 2u);
  EXPECT_EQ(map->uv.size(), size_t(mesh.vertex_count())) << "the patches' centres are dropped";
  EXPECT_TRUE(map->parameterization.quality.bijective());
  EXPECT_EQ(map->parameterization.quality.boundary_intersections, 0);
  const std::vector<glm::dvec2> outer = test::loop_polygon(*map, 0);
  EXPECT_GT(test::signed_area2(outer), 0) << "the outer loop runs counter-clockwise";
  for (size_t l = 1; l < mesh.boundary_loops.size(); ++l) {
    const std::vector<glm::dvec2> hole = test::loop_polygon(*map, l);
    EXPECT_LT(test::signed_area2(hole), 0) << "hole " << l << " runs clockwise";
    for (glm::dvec2 p : hole) EXPECT_TRUE(test::inside(outer, p)) << "hole " << l << " leaves the outer loop";
    for (size_t other = 1; other < mesh.boundary_loops.size(); ++other) {
      if (other == l) continue;
      const std::vector<glm::dvec2> second = test::loop_polygon(*map, other);
      for (glm::dvec2 p : hole) EXPECT_FALSE(test::inside(second, p)) << "hole " << l << " enters hole " << other;
    }
  }
  // No point of the surface's map lies inside a hole: each vertex is on a loop or outside all holes.
  std::vector<char> on_loop(mesh.vertex_count(), 0);
  for (const auto& loop : mesh.boundary_loops)
    for (int v : loop) on_loop[v] = 1;
  for (int v = 0; v < mesh.vertex_count(); ++v) {
    if (on_loop[v]) continue;
    for (size_t l = 1; l < mesh.boundary_loops.size(); ++l)
      ASSERT_FALSE(test::inside(test::loop_polygon(*map, l), map->uv[v])) << "vertex " << v << " in hole " << l;
  }
}

INSTANTIATE_TEST_SUITE_P(Surfaces, HoledMap, ::testing::ValuesIn(test::holed_surface_names()));

}  // namespace
}  // namespace paver
