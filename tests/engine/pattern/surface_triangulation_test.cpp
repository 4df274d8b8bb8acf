#include "pattern/surface_triangulation.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>
#include <random>
#include <set>
#include <utility>

namespace paver {
namespace {

double signed_area(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
  return 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

// Every triangle positive, every interior edge shared by exactly two triangles in opposite
// directions, and the areas summing to the hull's: a triangulation with no folds or gaps.
void expect_valid(const std::vector<glm::ivec3>& tris, const std::vector<glm::dvec2>& p, double hull_area) {
  std::set<std::pair<int, int>> half_edges;
  double area = 0;
  for (const glm::ivec3& t : tris) {
    EXPECT_GT(signed_area(p[t.x], p[t.y], p[t.z]), 0);
    area += signed_area(p[t.x], p[t.y], p[t.z]);
    for (int k = 0; k < 3; ++k) EXPECT_TRUE(half_edges.insert({t[k], t[(k + 1) % 3]}).second) << "edge used twice";
  }
  EXPECT_NEAR(area, hull_area, 1e-9 * hull_area);
}

TEST(DelaunayTriangulation, RandomPointsHaveEmptyCircumcircles) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<glm::dvec2> p = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int i = 0; i < 400; ++i) p.push_back({u(rng), u(rng)});
  const auto tris = delaunay_triangulation(p);
  expect_valid(tris, p, 1.0);
  EXPECT_EQ(tris.size(), 2 * p.size() - 2 - 4);  // 2n - 2 - hull points
  for (const glm::ivec3& t : tris) {
    const glm::dvec2 a = p[t.x], b = p[t.y], c = p[t.z];
    const double d = 2 * (a.x * (b.y - c.y) + b.x * (c.y - a.y) + c.x * (a.y - b.y));
    const glm::dvec2 centre((glm::dot(a, a) * (b.y - c.y) + glm::dot(b, b) * (c.y - a.y) + glm::dot(c, c) * (a.y - b.y)) / d,
                            (glm::dot(a, a) * (c.x - b.x) + glm::dot(b, b) * (a.x - c.x) + glm::dot(c, c) * (b.x - a.x)) / d);
    const double r = glm::length(a - centre);
    for (size_t i = 0; i < p.size(); ++i) EXPECT_GE(glm::length(p[i] - centre), r * (1 - 1e-9));
  }
}

TEST(DelaunayTriangulation, CocircularLatticeAndDuplicatesStayValid) {
  std::vector<glm::dvec2> p;
  for (int y = 0; y <= 20; ++y)
    for (int x = 0; x <= 20; ++x) p.push_back({x * 0.1, y * 0.1});
  p.push_back(p[17]);  // a duplicate must not break it
  const auto tris = delaunay_triangulation(p);
  expect_valid(tris, p, 4.0);
  EXPECT_EQ(tris.size(), 2u * 20 * 20);
}

TEST(SurfaceTriangulation, FlipsFollowTheSurfaceNotTheShearedMap) {
  // A regular triangle lattice on the plane z = 0, seen through a map that squeezes y by 6: in the
  // map the short diagonals are the other ones, on the surface every triangle is equilateral.
  std::vector<glm::dvec2> uv;
  std::vector<glm::dvec3> xyz;
  const double h = std::sqrt(3.0) / 2;
  for (int row = 0; row < 12; ++row)
    for (int col = 0; col < 12; ++col) {
      const glm::dvec3 p(col + 0.5 * (row % 2), row * h, 0);
      xyz.push_back(p);
      uv.push_back({p.x, p.y / 6});
    }
  const auto tris = triangulate_surface_points(uv, xyz, 1.5);
  ASSERT_FALSE(tris.empty());
  int equilateral = 0;
  for (const glm::ivec3& t : tris) {
    bool ok = true;
    for (int k = 0; k < 3; ++k) ok = ok && std::abs(glm::length(xyz[t[k]] - xyz[t[(k + 1) % 3]]) - 1) < 1e-9;
    equilateral += ok;
    EXPECT_GT(signed_area(uv[t.x], uv[t.y], uv[t.z]), 0);
  }
  EXPECT_EQ(equilateral, int(tris.size()));
  EXPECT_GE(tris.size(), 2u * 11 * 11 - 11);
  // The plain Delaunay triangulation of the map has long 3D edges: the flips are what fixed them.
  const auto plain = delaunay_triangulation(uv);
  int long_edges = 0;
  for (const glm::ivec3& t : plain)
    for (int k = 0; k < 3; ++k) long_edges += glm::length(xyz[t[k]] - xyz[t[(k + 1) % 3]]) > 1.5;
  EXPECT_GT(long_edges, 100);
}

}  // namespace
}  // namespace paver
