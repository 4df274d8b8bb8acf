#include "surface_pick.h"

#include "map/lifting.h"
#include "surface_maps.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace paver::studio {
namespace {

// A ray straight down the normal onto a triangle's centroid meets that triangle there, and its
// map point is the centroid's; a ray that looks away from the surface meets nothing.
TEST(SurfacePick, ARayMeetsTheTriangleUnderItAndGivesItsMapPoint) {
  const SurfaceMap& map = *test::bundled_map("dome");
  const SurfaceMesh& mesh = map.mesh;
  for (const int t : {0, mesh.face_count() / 2, mesh.face_count() - 1}) {
    const glm::ivec3 f = mesh.triangles[std::size_t(t)];
    const glm::dvec3 a = mesh.positions[std::size_t(f.x)], b = mesh.positions[std::size_t(f.y)],
                     c = mesh.positions[std::size_t(f.z)];
    const glm::dvec3 centroid = (a + b + c) / 3.0, normal = glm::normalize(glm::cross(b - a, c - a));
    const double edge = glm::length(b - a);
    // From just above the triangle (a tenth of an edge) so that no other part of the dome is hit first.
    const std::optional<SurfaceHit> hit = first_hit(mesh, centroid + 0.1 * edge * normal, -normal);
    ASSERT_TRUE(hit) << "triangle " << t;
    EXPECT_EQ(hit->triangle, t);
    EXPECT_NEAR(hit->bary.x, 1.0 / 3, 1e-9);
    EXPECT_NEAR(hit->bary.y, 1.0 / 3, 1e-9);
    EXPECT_NEAR(hit->distance, 0.1 * edge, 1e-9 * edge);
    const glm::dvec2 expected = (map.uv[std::size_t(f.x)] + map.uv[std::size_t(f.y)] + map.uv[std::size_t(f.z)]) / 3.0;
    EXPECT_NEAR(glm::length(map_point(map, hit->triangle, hit->bary) - expected), 0, 1e-9);
    EXPECT_FALSE(first_hit(mesh, centroid + 1e6 * normal, normal)) << "looking away from the dome";
  }
}

}  // namespace
}  // namespace paver::studio
