#include "report/lattice_valence.h"

#include <gtest/gtest.h>

#include <cmath>

namespace paver {
namespace {

void add_vertex(Elements& e, glm::dvec2 p) {
  e.push_back(ElementKind::Vertex, int(e.size()), 0, p, {p.x, p.y, 0}, {0, 0, 1}, 0.5, ShapeKind::Sphere);
}

// A flat triangle lattice of spacing 1, `n` x `n` points, a little sheared so no four points are
// cocircular; `skip` (if in range) left out.
Elements triangle_lattice(int n, int skip = -1) {
  Elements e;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if (j * n + i != skip) add_vertex(e, {i + 0.5 * j + 1e-3 * j * j, j * std::sqrt(3.0) / 2});
  return e;
}

int valence_at(const Elements& e, const std::vector<int>& valence, glm::dvec2 p) {
  for (size_t i = 0; i < e.size(); ++i)
    if (std::abs(e.uv[i].x - p.x) < 0.1 && std::abs(e.uv[i].y - p.y) < 0.1) return valence[i];
  return -2;
}

TEST(LatticeValence, ATriangleLatticeIsSixValentInsideAndItsHoleLeavesFiveValentNeighbours) {
  const Elements full = triangle_lattice(10);
  const std::vector<int> v = lattice_valences(full, 6, 1);
  const glm::dvec2 inner(5 + 0.5 * 5 + 1e-3 * 25, 5 * std::sqrt(3.0) / 2);
  EXPECT_EQ(valence_at(full, v, inner), 6);
  int six = 0;
  for (int x : v) six += x == 6;
  EXPECT_GE(six, 8 * 8);  // every point off the rim

  const Elements holed = triangle_lattice(10, 5 * 10 + 5);
  const std::vector<int> w = lattice_valences(holed, 6, 1);
  EXPECT_EQ(valence_at(holed, w, inner), -2);  // gone
  // The hole is triangulated across: its six neighbours lose it, three of them gain a diagonal.
  int below_six = 0;
  for (size_t i = 0; i < holed.size(); ++i)
    if (std::hypot(holed.uv[i].x - inner.x, holed.uv[i].y - inner.y) < 1.1) below_six += w[i] < 6;
  EXPECT_GE(below_six, 2);
}

// A band: a triangle lattice on a cylinder of 40 points round, period 40 in u. Every point off
// the rims is 6-valent, across the seam too, and still when some points' u lies a period off either
// way (refill does not wrap what it adds).
TEST(LatticeValence, ABandIsSixValentAcrossItsSeamWhereverItsPointsLie) {
  constexpr int kRound = 40, kRows = 8;
  const double period = kRound, radius = kRound / (2 * std::acos(-1.0));
  for (const bool unwrapped : {false, true}) {
    Elements e;
    for (int j = 0; j < kRows; ++j)
      for (int i = 0; i < kRound; ++i) {
        double u = i + 0.5 * (j % 2) + 1e-3 * j;
        const double a = u / radius;
        if (unwrapped && i < 6) u += period;                // past the period's end
        if (unwrapped && i >= 20 && i < 26) u -= period;    // and before its start: u spans 1.5 periods
        e.push_back(ElementKind::Vertex, int(e.size()), 0, {u, j * std::sqrt(3.0) / 2},
                    {radius * std::cos(a), radius * std::sin(a), j * std::sqrt(3.0) / 2}, {0, 0, 1}, 0.5,
                    ShapeKind::Sphere);
      }
    const std::vector<int> v = lattice_valences(e, 6, 1, period);
    for (int j = 1; j + 1 < kRows; ++j)
      for (int i = 0; i < kRound; ++i) EXPECT_EQ(v[j * kRound + i], 6) << "row " << j << " point " << i << (unwrapped ? " (unwrapped)" : "");
  }
}

TEST(LatticeValence, AHoneycombHasThreeNeighboursInItsShellAndEdgeElementsHaveNone) {
  Elements e;
  // Honeycomb of edge 1: two points per cell of the triangle lattice of spacing sqrt 3.
  const double a = std::sqrt(3.0);
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) {
      const glm::dvec2 o(a * i + 0.5 * a * j, 1.5 * j);
      add_vertex(e, o);
      add_vertex(e, o + glm::dvec2(0, 1));
    }
  e.push_back(ElementKind::Edge, 0, 0, {0, 0.5}, {0, 0.5, 0}, {0, 0, 1}, 0.3, ShapeKind::Sphere);
  const std::vector<int> v = lattice_valences(e, 3, 1);
  EXPECT_EQ(v.back(), -1);
  int three = 0;
  for (size_t i = 0; i + 1 < e.size(); ++i) {
    EXPECT_LE(v[i], 3);
    three += v[i] == 3;
  }
  EXPECT_GE(three, 6 * 6 * 2);
}

}  // namespace
}  // namespace paver
