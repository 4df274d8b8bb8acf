// Tests for engine/pattern/pattern.cpp and engine/pattern/placement.cpp: the trimmed pattern holds exactly
// the lattice points inside the map and the lattice edges between them, the placement moves the
// lattice as section 4.2 says, and a spacing too small for the surface is refused with a fix.
#include "core/input_error.h"
#include "map/lifting.h"
#include "mesh/mesh_loader.h"
#include "pattern/pattern.h"
#include "design/placement.h"
#include "map/surface_map.h"
#include "mesh/surface_mesh.h"
#include "pattern/unit_cell.h"

#include "surface_maps.h"

#include "map_polygon.h"

#include <gtest/gtest.h>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <random>
#include <set>
#include <string>
#include <tuple>
#include <vector>

namespace paver {
namespace {

using test::boundary_polygon;
using test::inside;

constexpr double kSide = 10;  // L: the flat square is [0, L]^2 before parameterization
constexpr int kQuads = 10;    // quads per side of the flat square's triangulation

// The flat square [0, L]^2 in the z = 0 plane, n x n quads each split into two triangles.
SurfaceMesh flat_square(double side, int n) {
  std::vector<glm::dvec3> positions;
  std::vector<std::vector<int>> faces;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) positions.emplace_back(side * i / n, side * j / n, 0.0);
  auto id = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return make_surface(std::move(positions), faces, "flat square").mesh;
}

const SurfaceMap& flat_map() {
  static const SurfaceMap map = build_surface_map(flat_square(kSide, kQuads));
  return map;
}

const SurfaceMap& dome_map() { return *test::bundled_map("dome"); }

double distance_to_boundary(const std::vector<glm::dvec2>& polygon, glm::dvec2 p) {
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const glm::dvec2 a = polygon[j], ab = polygon[i] - a;
    const double t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
    best = std::min(best, glm::length(p - (a + t * ab)));
  }
  return best;
}

// What build_pattern should produce, counted independently: every lattice vertex over the map is
// tested against the boundary polygon.
struct Expected {
  int points = 0;
  int edges = 0;
  int crossing = 0;
  double margin = std::numeric_limits<double>::infinity();  // closest lattice vertex to the boundary
};

Expected enumerate(const SurfaceMap& map, const UnitCell& cell, const Placement& placement) {
  const std::vector<glm::dvec2> polygon = boundary_polygon(map);
  // Lattice coordinates of the map's bounding box corners in the pattern plane.
  const double det = cell.cell_area();
  glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi = -lo;
  for (glm::dvec2 corner : {map.uv_min, map.uv_max, glm::dvec2(map.uv_min.x, map.uv_max.y),
                            glm::dvec2(map.uv_max.x, map.uv_min.y)}) {
    const glm::dvec2 p = placement.map_to_pattern(corner);
    const glm::dvec2 l((p.x * cell.a2.y - p.y * cell.a2.x) / det, (cell.a1.x * p.y - cell.a1.y * p.x) / det);
    lo = glm::min(lo, l), hi = glm::max(hi, l);
  }
  const int x0 = int(std::floor(lo.x)) - 4, x1 = int(std::ceil(hi.x)) + 4;
  const int y0 = int(std::floor(lo.y)) - 4, y1 = int(std::ceil(hi.y)) + 4;
  auto is_inside = [&](int v, glm::ivec2 c, Expected& out) {
    const glm::dvec2 q = placement.pattern_to_map(cell.position(v, c));
    out.margin = std::min(out.margin, distance_to_boundary(polygon, q));
    return inside(polygon, q);
  };
  Expected out;
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const glm::ivec2 c(x, y);
      for (int v = 0; v < int(cell.vertices.size()); ++v) out.points += is_inside(v, c, out) ? 1 : 0;
      for (const CellEdge& e : cell.edges) {
        const bool a = is_inside(e.from, c, out), b = is_inside(e.to, c + e.offset, out);
        if (a && b) ++out.edges;
        else if (a != b && !e.is_virtual) ++out.crossing;
      }
    }
  return out;
}

// The pattern matches the independent count, and every point and edge is where the lattice says.
void expect_pattern_matches_lattice(const SurfaceMap& map, const UnitCell& cell, const Placement& placement,
                                    const Pattern& pattern) {
  const Expected expected = enumerate(map, cell, placement);
  // A lattice vertex on the boundary would make the expected count a matter of rounding.
  ASSERT_GT(expected.margin, 1e-6 * cell.spacing) << "test setup puts a lattice vertex on the boundary";
  EXPECT_EQ(pattern.point_count(), expected.points);
  EXPECT_EQ(pattern.edge_count(), expected.edges);
  EXPECT_EQ(int(pattern.crossing_edges.size()), expected.crossing);

  ASSERT_EQ(pattern.point_cell_vertex.size(), pattern.points.size());
  ASSERT_EQ(pattern.point_cell.size(), pattern.points.size());
  const std::vector<glm::dvec2> polygon = boundary_polygon(map);
  const double tol = 1e-9 * cell.spacing;
  std::set<std::tuple<int, int, int>> seen;
  for (int p = 0; p < pattern.point_count(); ++p) {
    EXPECT_TRUE(inside(polygon, pattern.points[p])) << "point " << p << " is outside the map";
    const int v = pattern.point_cell_vertex[p];
    const glm::ivec2 c = pattern.point_cell[p];
    ASSERT_GE(v, 0);
    ASSERT_LT(v, int(cell.vertices.size()));
    EXPECT_TRUE(seen.emplace(c.x, c.y, v).second) << "lattice vertex instantiated twice";
    EXPECT_LE(glm::length(pattern.points[p] - placement.pattern_to_map(cell.position(v, c))), tol);
  }

  ASSERT_EQ(pattern.edge_b.size(), pattern.edge_a.size());
  ASSERT_EQ(pattern.edge_cell_edge.size(), pattern.edge_a.size());
  ASSERT_EQ(pattern.edge_rest_length.size(), pattern.edge_a.size());
  ASSERT_EQ(pattern.edge_virtual.size(), pattern.edge_a.size());
  for (int e = 0; e < pattern.edge_count(); ++e) {
    const int a = pattern.edge_a[e], b = pattern.edge_b[e], ce = pattern.edge_cell_edge[e];
    ASSERT_GE(a, 0);
    ASSERT_LT(a, pattern.point_count());
    ASSERT_GE(b, 0);
    ASSERT_LT(b, pattern.point_count());
    ASSERT_GE(ce, 0);
    ASSERT_LT(ce, int(cell.edges.size()));
    const CellEdge& edge = cell.edges[ce];
    EXPECT_EQ(pattern.point_cell_vertex[a], edge.from);
    EXPECT_EQ(pattern.point_cell_vertex[b], edge.to);
    EXPECT_EQ(pattern.point_cell[b] - pattern.point_cell[a], edge.offset);
    EXPECT_EQ(pattern.edge_rest_length[e], edge.rest_length);
    EXPECT_EQ(pattern.edge_virtual[e], edge.is_virtual ? 1 : 0);
    // In the map frame the lattice is scaled by 1 / placement.scale.
    EXPECT_NEAR(glm::length(pattern.points[b] - pattern.points[a]), edge.rest_length / placement.scale,
                1e-9 * edge.rest_length);
  }

  for (const Pattern::CrossingEdge& x : pattern.crossing_edges) {
    ASSERT_GE(x.inside_point, 0);
    ASSERT_LT(x.inside_point, pattern.point_count());
    ASSERT_GE(x.cell_edge, 0);
    ASSERT_LT(x.cell_edge, int(cell.edges.size()));
    const CellEdge& edge = cell.edges[x.cell_edge];
    EXPECT_FALSE(edge.is_virtual);
    EXPECT_TRUE(inside(polygon, pattern.points[x.inside_point]));
    EXPECT_FALSE(inside(polygon, x.outside)) << "crossing edge's outer end is inside the map";
    EXPECT_EQ(pattern.point_cell_vertex[x.inside_point], x.inside_is_from ? edge.from : edge.to);
    // From the `from` end to the `to` end is the cell's edge vector, seen in the map frame.
    const glm::dvec2 from = x.inside_is_from ? pattern.points[x.inside_point] : x.outside;
    const glm::dvec2 to = x.inside_is_from ? x.outside : pattern.points[x.inside_point];
    const glm::dvec2 expected_to = placement.pattern_to_map(placement.map_to_pattern(from) + cell.edge_vector(edge));
    EXPECT_LE(glm::length(to - expected_to), tol);
  }
}

TEST(PatternPlacement, MapToPatternFollowsTheFormula) {
  // p = R(rotation) (scale q) + offset: (1, 0) scaled by 2 is (2, 0), turned 90 degrees (0, 2),
  // moved by (3, 4) to (3, 6).
  Placement placement;
  placement.scale = 2, placement.rotation_deg = 90, placement.offset = {3, 4};
  const glm::dvec2 p = placement.map_to_pattern({1, 0});
  EXPECT_NEAR(p.x, 3, 1e-12);
  EXPECT_NEAR(p.y, 6, 1e-12);
  const glm::dvec2 q = placement.pattern_to_map({3, 6});
  EXPECT_NEAR(q.x, 1, 1e-12);
  EXPECT_NEAR(q.y, 0, 1e-12);
  // Identity by default.
  const glm::dvec2 same = Placement{}.map_to_pattern({-1.5, 2.25});
  EXPECT_EQ(same, glm::dvec2(-1.5, 2.25));
}

TEST(PatternPlacement, MapToPatternAndBackAreInverses) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coord(-50, 50), angle(-360, 360), scale(0.1, 10);
  for (int i = 0; i < 200; ++i) {
    Placement placement;
    placement.offset = {coord(rng), coord(rng)};
    placement.rotation_deg = angle(rng);
    placement.scale = scale(rng);
    const glm::dvec2 q(coord(rng), coord(rng));
    const glm::dvec2 p = placement.map_to_pattern(q);
    EXPECT_LE(glm::length(placement.pattern_to_map(p) - q), 1e-9 * 50) << i;
    EXPECT_LE(glm::length(placement.map_to_pattern(placement.pattern_to_map(q)) - q), 1e-9 * 50) << i;
    // A similarity: distances from the offset grow by `scale`.
    EXPECT_NEAR(glm::length(p - placement.offset), placement.scale * glm::length(q), 1e-9 * 50 * placement.scale);
  }
}

TEST(PatternFlatSquare, TheMapIsTheSquareUpToAMotion) {
  // Everything below relies on the flat square's map being isometric and centred at the origin.
  const SurfaceMap& map = flat_map();
  EXPECT_EQ(map.mesh.outer_loop().size(), size_t(4 * kQuads));
  glm::dvec2 centre(0);
  for (const glm::dvec2& q : map.uv) centre += q;
  centre /= double(map.uv.size());
  EXPECT_LE(glm::length(centre), 1e-9 * kSide);
  for (const glm::ivec3& t : map.mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      EXPECT_NEAR(glm::length(map.uv[b] - map.uv[a]), glm::length(map.mesh.positions[b] - map.mesh.positions[a]),
                  1e-6 * kSide / kQuads);
    }
}

struct FlatCase {
  Tessellation tessellation;
  double spacing;
};

class PatternOnFlatSquare : public ::testing::TestWithParam<FlatCase> {};

TEST_P(PatternOnFlatSquare, HoldsExactlyTheLatticeInsideTheMap) {
  const UnitCell cell = make_unit_cell(GetParam().tessellation, GetParam().spacing);
  const Pattern pattern = build_pattern(flat_map(), cell, {});
  expect_pattern_matches_lattice(flat_map(), cell, {}, pattern);
  EXPECT_GT(pattern.point_count(), 0);
  EXPECT_GT(pattern.crossing_edges.size(), 0u);
}

TEST_P(PatternOnFlatSquare, EdgesLiftToLengthDOnTheFlatSurface) {
  const UnitCell cell = make_unit_cell(GetParam().tessellation, GetParam().spacing);
  const SurfaceMap& map = flat_map();
  const Pattern pattern = build_pattern(map, cell, {});
  ASSERT_GT(pattern.edge_count(), 0);
  LiftedPoints lifted;
  lifted.resize(pattern.points.size());
  ASSERT_EQ(lift_points(map, pattern.points, lifted), 0);
  const double d = cell.spacing;
  for (int p = 0; p < pattern.point_count(); ++p) EXPECT_NEAR(lifted.position[p].z, 0, 1e-9 * kSide);
  for (int e = 0; e < pattern.edge_count(); ++e) {
    const double in_plane = glm::length(pattern.points[pattern.edge_b[e]] - pattern.points[pattern.edge_a[e]]);
    const double on_surface =
        glm::length(lifted.position[pattern.edge_b[e]] - lifted.position[pattern.edge_a[e]]);
    EXPECT_NEAR(in_plane, d, 1e-6 * d) << "edge " << e;
    EXPECT_NEAR(on_surface, d, 1e-6 * d) << "edge " << e;
  }
}

// D = 0.7 keeps every lattice vertex at least 0.1 away from the square's sides (|x| = 5 is not a
// multiple of 0.35, of sqrt(3)/2 * 0.7, nor hit by the honeycomb's rows).
INSTANTIATE_TEST_SUITE_P(Pattern, PatternOnFlatSquare,
                         ::testing::Values(FlatCase{Tessellation::Grid, 0.7}, FlatCase{Tessellation::Triangle, 0.7},
                                           FlatCase{Tessellation::Hexagon, 0.7}),
                         [](const auto& info) { return std::string(enum_name(info.param.tessellation)); });

TEST(PatternFlatSquare, GridCountIsTheLatticeInsideTheSquare) {
  // The flat square with its own coordinates as the map, centred: [-5, 5]^2. It holds the grid
  // points i * 0.7 with |i| <= 7 along each axis (7 * 0.7 = 4.9): 15 x 15 points, 2 * 15 * 14
  // edges between them, and the 4 * 15 lattice edges that leave through the sides cross.
  SurfaceMesh mesh = flat_square(kSide, kQuads);
  std::vector<glm::dvec2> uv;
  for (const glm::dvec3& p : mesh.positions) uv.emplace_back(p.x - kSide / 2, p.y - kSide / 2);
  const SurfaceMap map = make_surface_map(std::move(mesh), std::move(uv));
  const UnitCell cell = make_unit_cell(Tessellation::Grid, 0.7);
  const Pattern pattern = build_pattern(map, cell, {});
  EXPECT_EQ(pattern.point_count(), 15 * 15);
  EXPECT_EQ(pattern.edge_count(), 2 * 15 * 14);
  EXPECT_EQ(int(pattern.crossing_edges.size()), 4 * 15);
  for (const glm::dvec2& q : pattern.points) {
    EXPECT_LE(std::abs(q.x), 4.9 + 1e-9);
    EXPECT_LE(std::abs(q.y), 4.9 + 1e-9);
  }
  // The parameterized square has the same count, whatever its orientation in the plane.
  expect_pattern_matches_lattice(flat_map(), cell, {}, build_pattern(flat_map(), cell, {}));
}

TEST(PatternFlatSquare, QuarterTurnOfTheGridKeepsTheCount) {
  // The square map is centred at the origin, so a quarter turn maps it onto itself and the grid
  // onto itself: the same lattice points fall inside.
  const UnitCell cell = make_unit_cell(Tessellation::Grid, 0.7);
  const Pattern straight = build_pattern(flat_map(), cell, {});
  Placement turned;
  turned.rotation_deg = 90;
  const Pattern rotated = build_pattern(flat_map(), cell, turned);
  EXPECT_EQ(rotated.point_count(), straight.point_count());
  EXPECT_EQ(rotated.edge_count(), straight.edge_count());
  EXPECT_EQ(rotated.crossing_edges.size(), straight.crossing_edges.size());
  expect_pattern_matches_lattice(flat_map(), cell, turned, rotated);
}

TEST(PatternFlatSquare, OffsetByALatticeVectorKeepsTheCount) {
  for (Tessellation t : {Tessellation::Grid, Tessellation::Triangle, Tessellation::Hexagon}) {
    const UnitCell cell = make_unit_cell(t, 0.7);
    const Pattern straight = build_pattern(flat_map(), cell, {});
    for (glm::dvec2 shift : {cell.a1, cell.a2, cell.a1 - 2.0 * cell.a2}) {
      Placement moved;
      moved.offset = shift;
      const Pattern pattern = build_pattern(flat_map(), cell, moved);
      EXPECT_EQ(pattern.point_count(), straight.point_count()) << enum_name(t);
      EXPECT_EQ(pattern.edge_count(), straight.edge_count()) << enum_name(t);
      // The points are the same points in the map frame.
      for (const glm::dvec2& q : pattern.points) {
        double nearest = std::numeric_limits<double>::infinity();
        for (const glm::dvec2& r : straight.points) nearest = std::min(nearest, glm::length(q - r));
        EXPECT_LE(nearest, 1e-9 * cell.spacing) << enum_name(t);
      }
    }
  }
}

TEST(PatternFlatSquare, DoublingTheScaleRoughlyQuadruplesTheCount) {
  const UnitCell cell = make_unit_cell(Tessellation::Grid, 0.7);
  const Pattern base = build_pattern(flat_map(), cell, {});
  Placement bigger;
  bigger.scale = 2;
  const Pattern pattern = build_pattern(flat_map(), cell, bigger);
  const double ratio = double(pattern.point_count()) / base.point_count();
  EXPECT_GT(ratio, 3.5);
  EXPECT_LT(ratio, 4.5);
  expect_pattern_matches_lattice(flat_map(), cell, bigger, pattern);
}

TEST(PatternFlatSquare, AnyPlacementHoldsExactlyTheLatticeInsideTheMap) {
  // Awkward placements, still with every lattice vertex clear of the boundary (checked).
  const UnitCell hex = make_unit_cell(Tessellation::Hexagon, 0.7);
  Placement placement;
  placement.rotation_deg = 17, placement.offset = {0.23, -0.41}, placement.scale = 1.3;
  expect_pattern_matches_lattice(flat_map(), hex, placement, build_pattern(flat_map(), hex, placement));

  UnitCell braced = make_unit_cell(Tessellation::Grid, 0.7);
  add_bracing_edges(braced);
  placement.rotation_deg = -35, placement.offset = {0.05, 0.31}, placement.scale = 0.8;
  const Pattern pattern = build_pattern(flat_map(), braced, placement);
  expect_pattern_matches_lattice(flat_map(), braced, placement, pattern);
  int virtual_edges = 0;
  for (std::uint8_t v : pattern.edge_virtual) virtual_edges += v;
  EXPECT_GT(virtual_edges, 0);
}

TEST(PatternDome, HoldsExactlyTheLatticeInsideTheMap) {
  const UnitCell cell = make_unit_cell(Tessellation::Hexagon, 6);
  const Pattern pattern = build_pattern(dome_map(), cell, {});
  expect_pattern_matches_lattice(dome_map(), cell, {}, pattern);
}

TEST(PatternDome, EstimateIsWithinTenPercentOfTheCount) {
  const UnitCell cell = make_unit_cell(Tessellation::Hexagon, 6);
  const double estimate = estimate_point_count(dome_map(), cell, {});
  // Area over the cell's area, two points per hexagonal cell of area 3 sqrt(3) / 2 D^2.
  EXPECT_NEAR(estimate, surface_area(dome_map().mesh) * 2 / (1.5 * std::sqrt(3.0) * 36), 1e-9 * estimate);
  const Pattern pattern = build_pattern(dome_map(), cell, {});
  EXPECT_NEAR(pattern.point_count(), estimate, 0.1 * estimate);
  // The estimate follows the placement's scale: the map's area grows with its square.
  Placement half;
  half.scale = 0.5;
  EXPECT_NEAR(estimate_point_count(dome_map(), cell, half), estimate / 4, 1e-9 * estimate);
}

// The number printed after `label` in `text`.
double number_after(const std::string& text, const std::string& label) {
  const size_t at = text.find(label);
  if (at == std::string::npos) {
    ADD_FAILURE() << "'" << text << "' does not contain '" << label << "'";
    return std::nan("");
  }
  return std::strtod(text.c_str() + at + label.size(), nullptr);
}

TEST(PatternDome, AbsurdSpacingIsRefusedWithASpacingThatWorks) {
  const SurfaceMap& dome = dome_map();
  const double area = surface_area(dome.mesh);
  for (double d : {1e-4, 1.3e-4, 2.9e-4, 7.7e-4}) {
    const UnitCell cell = make_unit_cell(Tessellation::Hexagon, d);
    std::string message;
    try {
      build_pattern(dome, cell, {});
      ADD_FAILURE() << "D = " << d << " was accepted";
      continue;
    } catch (const InputError& e) {
      message = e.what();
    }
    SCOPED_TRACE(message);
    // Two points per hexagonal cell of area 3 sqrt(3) / 2 D^2.
    const double points = area * 2 / (1.5 * std::sqrt(3.0) * d * d);
    EXPECT_NEAR(number_after(message, "would create about "), points, 0.005 * points);
    // The smallest spacing that stays under the limit, D sqrt(points / limit), up to the printed
    // precision; and the spacing suggested must itself be accepted.
    const double smallest = d * std::sqrt(points / kMaxPatternPoints);
    const double suggested = number_after(message, "spacing of at least ");
    EXPECT_NEAR(suggested, smallest, 0.005 * smallest);
    EXPECT_LE(estimate_point_count(dome, make_unit_cell(Tessellation::Hexagon, suggested), {}), kMaxPatternPoints)
        << "the suggested spacing " << suggested << " is refused too";
  }
}

// F-elements' faces: every face listed has its corners joined by the pattern's edges, none twice,
// and every point away from the rim lies in as many faces as it has edges (a vertex of degree d
// meets d faces), so no face inside the map is missing.
TEST(PatternFaces, EveryFaceInsideTheMapIsListedOnceWithItsCornersJoined) {
  const SurfaceMap& map = test::flat_unit_square();
  const std::vector<glm::dvec2> polygon = boundary_polygon(map);
  for (const Tessellation t : {Tessellation::Cairo, Tessellation::Prismatic, Tessellation::Triangle, Tessellation::Hexagon}) {
    SCOPED_TRACE(std::string(enum_name(t)));
    const UnitCell cell = make_unit_cell(t, 0.05);
    const Pattern without = build_pattern(map, cell, {});
    EXPECT_EQ(without.face_count(), 0) << "faces only when asked";
    const Pattern p = build_pattern(map, cell, {}, true);
    ASSERT_GT(p.face_count(), 100);
    std::set<std::pair<int, int>> joined;
    std::vector<int> degree(std::size_t(p.point_count()), 0);
    for (int e = 0; e < p.edge_count(); ++e)
      if (!p.edge_virtual[e]) {
        joined.insert(std::minmax(p.edge_a[e], p.edge_b[e]));
        ++degree[std::size_t(p.edge_a[e])], ++degree[std::size_t(p.edge_b[e])];
      }
    std::set<std::vector<int>> seen;
    std::vector<int> faces_at(std::size_t(p.point_count()), 0);
    for (int f = 0; f < p.face_count(); ++f) {
      std::vector<int> corners(p.face_corner.begin() + p.face_start[f], p.face_corner.begin() + p.face_start[f + 1]);
      ASSERT_EQ(corners.size(), cell_faces(cell).front().size());
      for (size_t k = 0; k < corners.size(); ++k) {
        EXPECT_TRUE(joined.count(std::minmax(corners[k], corners[(k + 1) % corners.size()])))
            << "face " << f << " side " << k;
        ++faces_at[std::size_t(corners[k])];
      }
      std::sort(corners.begin(), corners.end());
      EXPECT_TRUE(seen.insert(corners).second) << "face " << f << " listed twice";
    }
    int interior = 0;
    for (int i = 0; i < p.point_count(); ++i) {
      const glm::dvec2 q = p.points[std::size_t(i)];
      double rim = 1e300;  // distance to the boundary polygon
      for (size_t a = 0, b = polygon.size() - 1; a < polygon.size(); b = a++) {
        const glm::dvec2 ab = polygon[a] - polygon[b];
        const double t = std::clamp(glm::dot(q - polygon[b], ab) / glm::dot(ab, ab), 0.0, 1.0);
        rim = std::min(rim, glm::length(q - (polygon[b] + t * ab)));
      }
      if (rim < 0.3) continue;  // two Cairo cells' reach
      ++interior;
      EXPECT_EQ(faces_at[std::size_t(i)], degree[std::size_t(i)]) << "point " << i;
    }
    EXPECT_GE(interior, 40);
  }
}

}  // namespace
}  // namespace paver
