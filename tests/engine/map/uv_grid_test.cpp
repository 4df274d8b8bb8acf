// Tests for engine/map/uv_grid.cpp: on the maps of bundled surfaces, locate finds the triangle that
// contains a random point (checked against every triangle, with barycentric coordinates computed
// here), returns its barycentric coordinates, and returns -1 for points outside the map (in its
// bounding box or far away, or not a number). Points on shared edges and vertices get one of
// their triangles; every triangle is listed in the grid cells its corners fall in.
#include "map/uv_grid.h"

#include "map/surface_map.h"
#include "surface_maps.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace paver {
namespace {

const SurfaceMap& map_of(const std::string& name) { return *test::bundled_map(name); }

double cross(glm::dvec2 a, glm::dvec2 b) { return a.x * b.y - a.y * b.x; }

// Barycentric coordinates as signed sub-triangle areas over the triangle's area.
glm::dvec3 areas(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
  const double total = cross(b - a, c - a);
  return {cross(b - p, c - p) / total, cross(c - p, a - p) / total, cross(a - p, b - p) / total};
}

double lowest(glm::dvec3 w) { return std::min(w.x, std::min(w.y, w.z)); }

glm::dvec3 areas_in(const SurfaceMap& map, int t, glm::dvec2 p) {
  const glm::ivec3 tri = map.mesh.triangles[t];
  return areas(p, map.uv[tri.x], map.uv[tri.y], map.uv[tri.z]);
}

glm::dvec2 point_of(const SurfaceMap& map, int t, glm::dvec3 w) {
  const glm::ivec3 tri = map.mesh.triangles[t];
  return w.x * map.uv[tri.x] + w.y * map.uv[tri.y] + w.z * map.uv[tri.z];
}

int locate_in(const SurfaceMap& map, glm::dvec2 p, glm::dvec3& bary) {
  return locate(map.grid, map.uv, map.mesh.triangles, p, bary);
}

class UvGridLocate : public ::testing::TestWithParam<std::string> {};

TEST_P(UvGridLocate, RandomPointsAgreeWithEveryTriangle) {
  const SurfaceMap& map = map_of(GetParam());
  const glm::dvec2 size = map.uv_max - map.uv_min;
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(map.uv_min.x - 0.05 * size.x, map.uv_max.x + 0.05 * size.x);
  std::uniform_real_distribution<double> v(map.uv_min.y - 0.05 * size.y, map.uv_max.y + 0.05 * size.y);
  const double scale = std::max(size.x, size.y);
  int inside = 0, outside = 0, undecided = 0;
  for (int k = 0; k < 4000; ++k) {
    const glm::dvec2 p(u(rng), v(rng));
    // The triangle that contains p best, over all of them.
    int best = -1;
    double best_lowest = -std::numeric_limits<double>::infinity();
    for (int t = 0; t < map.mesh.face_count(); ++t) {
      const double l = lowest(areas_in(map, t, p));
      if (l > best_lowest) best_lowest = l, best = t;
    }
    glm::dvec3 bary(-7);
    const int found = locate_in(map, p, bary);
    if (best_lowest > 1e-9) {
      ++inside;
      ASSERT_EQ(found, best) << "point (" << p.x << ", " << p.y << ")";
      const glm::dvec3 want = areas_in(map, best, p);
      EXPECT_NEAR(bary.x, want.x, 1e-9);
      EXPECT_NEAR(bary.y, want.y, 1e-9);
      EXPECT_NEAR(bary.z, want.z, 1e-9);
      EXPECT_NEAR(glm::length(point_of(map, found, bary) - p), 0, 1e-9 * scale);
    } else if (best_lowest < -1e-9) {
      ++outside;
      EXPECT_EQ(found, -1) << "point (" << p.x << ", " << p.y << ") is outside the map";
    } else {
      ++undecided;
    }
  }
  EXPECT_GT(inside, 1000);
  EXPECT_GT(outside, 200);
  EXPECT_LE(undecided, 2);
}

TEST_P(UvGridLocate, PointsOnEdgesAndVerticesGetOneOfTheirTriangles) {
  const SurfaceMap& map = map_of(GetParam());
  const double scale = std::max(map.uv_max.x - map.uv_min.x, map.uv_max.y - map.uv_min.y);
  auto check = [&](glm::dvec2 p, const std::string& what) {
    glm::dvec3 bary;
    const int found = locate_in(map, p, bary);
    ASSERT_GE(found, 0) << what;
    EXPECT_GE(lowest(areas_in(map, found, p)), -1e-9) << what << " is not in triangle " << found;
    EXPECT_GE(lowest(bary), 0) << what;
    EXPECT_NEAR(bary.x + bary.y + bary.z, 1, 1e-12) << what;
    EXPECT_NEAR(glm::length(point_of(map, found, bary) - p), 0, 1e-9 * scale) << what;
  };
  for (int t = 0; t < map.mesh.face_count(); t += 7) {
    const glm::ivec3 tri = map.mesh.triangles[t];
    check(map.uv[tri.x], "vertex " + std::to_string(tri.x));
    check(0.5 * (map.uv[tri.x] + map.uv[tri.y]), "edge " + std::to_string(tri.x) + "-" + std::to_string(tri.y));
  }
  // The boundary itself belongs to the map.
  const auto& loop = map.mesh.outer_loop();
  for (size_t i = 0; i < loop.size(); ++i) {
    check(map.uv[loop[i]], "boundary vertex " + std::to_string(loop[i]));
    check(0.5 * (map.uv[loop[i]] + map.uv[loop[(i + 1) % loop.size()]]), "boundary edge " + std::to_string(i));
  }
}

TEST_P(UvGridLocate, FarAwayAndNonFinitePointsAreOutside) {
  const SurfaceMap& map = map_of(GetParam());
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  const glm::dvec2 mid = 0.5 * (map.uv_min + map.uv_max);
  for (glm::dvec2 p : {glm::dvec2(1e6, 1e6), glm::dvec2(-1e6, mid.y), glm::dvec2(mid.x, 1e300),
                       glm::dvec2(map.uv_max.x + 1e-3, mid.y), glm::dvec2(mid.x, map.uv_min.y - 1e-3),
                       glm::dvec2(nan, mid.y), glm::dvec2(mid.x, nan), glm::dvec2(inf, inf), glm::dvec2(-inf, mid.y)}) {
    glm::dvec3 bary;
    EXPECT_EQ(locate_in(map, p, bary), -1) << p.x << ", " << p.y;
  }
}

TEST_P(UvGridLocate, EveryTriangleIsListedInTheCellsOfItsCorners) {
  const SurfaceMap& map = map_of(GetParam());
  const UvGrid& g = map.grid;
  ASSERT_EQ(g.cell_start.size(), size_t(g.nx) * g.ny + 1);
  ASSERT_EQ(g.cell_start.front(), 0);
  ASSERT_EQ(size_t(g.cell_start.back()), g.cell_triangles.size());
  ASSERT_TRUE(std::is_sorted(g.cell_start.begin(), g.cell_start.end()));
  // About two triangles per cell, as built by default.
  EXPECT_LE(double(g.nx) * g.ny, map.mesh.face_count());
  for (int t = 0; t < map.mesh.face_count(); ++t) {
    const glm::ivec3 tri = map.mesh.triangles[t];
    for (int corner : {tri.x, tri.y, tri.z}) {
      const glm::ivec2 c(glm::floor((map.uv[corner] - g.origin) / g.cell_size));
      ASSERT_TRUE(c.x >= 0 && c.y >= 0 && c.x < g.nx && c.y < g.ny) << "vertex " << corner << " is off the grid";
      const size_t cell = size_t(c.y) * g.nx + c.x;
      const auto begin = g.cell_triangles.begin() + g.cell_start[cell], end = g.cell_triangles.begin() + g.cell_start[cell + 1];
      EXPECT_NE(std::find(begin, end, t), end) << "triangle " << t << " is missing from the cell of vertex " << corner;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(BundledSurfaces, UvGridLocate, ::testing::Values("dome", "pendant", "saddle"),
                         [](const auto& info) { return info.param; });

TEST(UvGridBuild, ASingleTriangleMapIsLocatedThroughSquareCells) {
  const std::vector<glm::dvec2> uv = {{0, 0}, {2, 0}, {0, 1}};
  const std::vector<glm::ivec3> triangles = {{0, 1, 2}};
  const UvGrid g = build_uv_grid(uv, triangles);
  EXPECT_EQ(g.nx * g.ny, 2) << "one cell of the box's area, square: 2 x 1";
  glm::dvec3 bary;
  EXPECT_EQ(locate(g, uv, triangles, {0.5, 0.25}, bary), 0);
  EXPECT_NEAR(bary.x, 0.5, 1e-15);
  EXPECT_NEAR(bary.y, 0.25, 1e-15);
  EXPECT_NEAR(bary.z, 0.25, 1e-15);
  EXPECT_EQ(locate(g, uv, triangles, {2, 0}, bary), 0) << "the far corner is on the grid";
  EXPECT_EQ(locate(g, uv, triangles, {1.5, 0.5}, bary), -1) << "in the box, beyond the hypotenuse";
}

}  // namespace
}  // namespace paver
