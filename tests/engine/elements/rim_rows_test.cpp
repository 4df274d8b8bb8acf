// Tests for engine/elements/rim_rows.cpp: on request, a row of stones follows each chosen rim,
// a radius plus the margin inside it, evenly spaced, the pattern making way; the pavement keeps
// the contact rule over all pairs, crosses no rim and still covers the surface. On the pierced
// pendant (three holes), the ring band (two rims, seamless) and the bead (seams are no rims).
#include "all_pairs.h"
#include "elements/rim_rows.h"
#include "map/boundary_index.h"
#include "mesh/mesh_loader.h"
#include "pattern/default_spacing.h"
#include "pipeline/pavement.h"
#include "report/verdict.h"
#include "plain_edges.h"
#include "surface_maps.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

namespace paver {
namespace {

Design design_for(const SurfaceMap& map, Tessellation tessellation, RimRows rows, double gap_share) {
  Design design;
  design.pattern.tessellation = tessellation;
  design.pattern.spacing = default_spacing(map.mesh, tessellation);
  design.elements.gap = gap_share * design.pattern.spacing;
  design.elements.vertex.scale = 1 - gap_share;
  design.elements.rim_rows = rows;
  return design;
}

// Index of the boundary loop nearest to p (3D, over every loop's segments).
int nearest_loop(const SurfaceMesh& mesh, const glm::dvec3& p) {
  int best_loop = -1;
  double best = std::numeric_limits<double>::infinity();
  for (int l = 0; l < int(mesh.boundary_loops.size()); ++l) {
    const std::vector<int>& loop = mesh.boundary_loops[l];
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const glm::dvec3 a = mesh.positions[loop[k]], b = mesh.positions[loop[(k + 1) % loop.size()]];
      const double t = std::clamp(glm::dot(p - a, b - a) / std::max(glm::dot(b - a, b - a), 1e-300), 0.0, 1.0);
      const double d = glm::length(p - (a + t * (b - a)));
      if (d < best) best = d, best_loop = l;
    }
  }
  return best_loop;
}

struct RowCheck {
  std::vector<int> per_loop;  // row elements whose nearest rim is each loop
  double worst_offset_error = 0;  // |distance to the rim - (radius + margin)|, x D
  double widest_step = 0;         // largest distance from a row element to its nearest row neighbour, x D
};

// The row elements: those that lie a radius plus the margin from a rim (within 2% of D); the
// widest step is taken over those of the rims the design asks a row for.
RowCheck check_rows(const SurfaceMap& map, const Pavement& p) {
  const std::vector<int> rims = rim_row_loops(map, p.design.elements.rim_rows);
  const double D = p.design.pattern.spacing;
  const double diameter = p.design.elements.vertex.scale * D;
  const double offset = 0.5 * diameter + p.design.elements.margin;
  const BoundaryIndex boundary(map.mesh, 4 * D);
  RowCheck check;
  check.per_loop.assign(map.mesh.boundary_loops.size(), 0);
  std::vector<glm::dvec3> row;
  for (std::size_t i = 0; i < p.elements.size(); ++i) {
    const double d = boundary.nearest(p.elements.position[i]).distance;
    if (std::abs(d - offset) > 0.02 * D) continue;
    const int loop = nearest_loop(map.mesh, p.elements.position[i]);
    ++check.per_loop[loop];
    if (std::find(rims.begin(), rims.end(), loop) != rims.end()) row.push_back(p.elements.position[i]);
    check.worst_offset_error = std::max(check.worst_offset_error, std::abs(d - offset) / D);
  }
  for (std::size_t i = 0; i < row.size(); ++i) {
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < row.size(); ++j)
      if (j != i) nearest = std::min(nearest, glm::length(row[i] - row[j]));
    check.widest_step = std::max(check.widest_step, nearest / D);
  }
  return check;
}

void expect_sound(const Pavement& p, const std::string& what) {
  const test::AllPairs truth = test::all_pairs(p.elements, p.design.elements.gap);
  EXPECT_EQ(truth.violations, 0) << what << ": smallest clearance " << truth.min_clearance;
  EXPECT_EQ(p.after.contact_violations, truth.violations) << what;
  EXPECT_EQ(p.after.boundary_crossings, 0) << what;
  EXPECT_GE(p.after.fill, 0.85) << what;
  // Sound; a few bare spots the closing could not reach behind a stepped hole's row, and the teeth
  // of metal a stepped rim leaves, are the verdict's to name (docs/contact.md), not this test's.
  const Verdict verdict = judge_pavement(p.after);
  EXPECT_TRUE(test::only_edge_problems(verdict.problems)) << what << ": " << test::all_problems(verdict.problems);
  EXPECT_LE(p.after.edges.bare_spots, 10) << what;
}

TEST(RimRows, EveryHoleOfThePiercedPendantGetsARowAndThePavementStaysSound) {
  const auto map = test::bundled_map("pendant_pierced");
  ASSERT_EQ(map->mesh.boundary_loops.size(), 4u);
  for (const Tessellation tessellation : {Tessellation::Triangle, Tessellation::Hexagon})
    for (const double gap_share : {0.0, 0.08}) {
      const std::string what = std::string(enum_name(tessellation)) + " gap " + std::to_string(gap_share);
      const Pavement without = make_pavement(*map, design_for(*map, tessellation, RimRows::None, gap_share));
      const Pavement with = make_pavement(*map, design_for(*map, tessellation, RimRows::Holes, gap_share));
      EXPECT_EQ(without.rim_rows.placed, 0) << what;
      EXPECT_EQ(with.rim_rows.loops, 3) << what;
      EXPECT_GE(with.rim_rows.placed, 3 * 5) << what;
      expect_sound(with, what);
      const RowCheck rows = check_rows(*map, with);
      // Each hole (loops 1-3) is ringed: at least the row's elements sit at the offset from it.
      for (int l = 1; l < 4; ++l) EXPECT_GE(rows.per_loop[l], 5) << what << " hole " << l;
      // A row, not scattered stones: every row element has a row neighbour within 2 D (the
      // piercings' rims are stepped: at a concave step one element may be left out).
      EXPECT_LE(rows.widest_step, 2.0) << what;
      // Trimmed, the pattern leaves fewer elements at that offset from the holes.
      const RowCheck trimmed = check_rows(*map, without);
      int ringed = 0, trimmed_ring = 0;
      for (int l = 1; l < 4; ++l) ringed += rows.per_loop[l], trimmed_ring += trimmed.per_loop[l];
      EXPECT_GT(ringed, trimmed_ring) << what;
    }
}

TEST(RimRows, AJewellersRowsAroundSteppedHolesTouchAlongThem) {
  // The jeweller's pierced pendant: 1.3 mm stones, 0.1 mm gap, 0.3 mm margin. Spaced by arc length,
  // the shortest chord (over a corner of a stepped rim) set the whole row's spacing: stones with
  // gaps between them all round. By chord they touch (through the gap) along each row.
  const auto map = test::bundled_map("pendant_pierced");
  Design design;
  design.elements.gap = 0.1;
  design.elements.margin = 0.3;
  set_stone_size(design, 1.3);
  design.elements.rim_rows = RimRows::Holes;
  Elements rows;
  const RimRowReport report = place_rim_rows(*map, rows, design.elements, design.pattern.spacing);
  ASSERT_EQ(report.loops, 3);
  const double contact = 1.3 + 0.1;
  std::vector<double> ratio;  // to the nearest other row stone, over the contact distance
  for (std::size_t i = 0; i < rows.size(); ++i) {
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < rows.size(); ++j)
      if (j != i) nearest = std::min(nearest, glm::length(rows.position[i] - rows.position[j]));
    EXPECT_GE(nearest / contact, 1.0 - 1e-9) << i;
    ratio.push_back(nearest / contact);
  }
  std::sort(ratio.begin(), ratio.end());
  // The count's leftover spread evenly (on the smallest hole, 9 stones, about a ninth); where a
  // stepped rim's concave corner drops its curve, one stone per hole may sit farther.
  EXPECT_LT(ratio[ratio.size() / 2], 1.06);
  EXPECT_LT(ratio[ratio.size() - 5], 1.13);
  EXPECT_GE(report.placed, 32);
}

TEST(RimRows, AllRimsIncludesTheOuterEdge) {
  const auto map = test::bundled_map("pendant_pierced");
  const Pavement p = make_pavement(*map, design_for(*map, Tessellation::Triangle, RimRows::All, 0));
  EXPECT_EQ(p.rim_rows.loops, 4);
  expect_sound(p, "all rims");
  EXPECT_GE(check_rows(*map, p).per_loop[0], 40);
  EXPECT_EQ(rim_row_loops(*map, RimRows::All).size(), 4u);
  EXPECT_EQ(rim_row_loops(*map, RimRows::Holes), (std::vector<int>{1, 2, 3}));
}

TEST(RimRows, ABandGetsARowAlongEachRimAcrossItsSeam) {
  const auto map = test::bundled_map("ring_band");
  const Pavement p = make_pavement(*map, design_for(*map, Tessellation::Triangle, RimRows::All, 0.05));
  EXPECT_TRUE(p.seamless);
  EXPECT_EQ(p.rim_rows.loops, 2);
  expect_sound(p, "ring band");
  const RowCheck rows = check_rows(*map, p);
  EXPECT_LE(rows.widest_step, 1.6);
  EXPECT_GE(rows.per_loop[0], 20);
  EXPECT_GE(rows.per_loop[1], 20);
}

// A ring's two rims are its edges, not a hole: "holes" lined one of them and left the ring
// lopsided (a jeweller's trial). A bangle's are alike too; the pierced pendant's holes are holes.
TEST(RimRows, ABandsAlikeRimsAreNoHoles) {
  for (const char* band : {"ring_band", "bangle"}) {
    const auto map = test::bundled_map(band);
    EXPECT_TRUE(band_rims_alike(*map)) << band;
    EXPECT_TRUE(rim_row_loops(*map, RimRows::Holes).empty()) << band;
    EXPECT_EQ(rim_row_loops(*map, RimRows::All).size(), 2u) << band;
  }
  EXPECT_FALSE(band_rims_alike(*test::bundled_map("pendant_pierced")));
  EXPECT_FALSE(band_rims_alike(*test::bundled_map("pendant")));
}

// A plate with a 20-degree tip: the row's offset curve turns sharply there, so elements two apart
// along it come closer than their neighbours; every row element is checked against every other.
TEST(RimRows, ASharpTipKeepsTheContactRuleAlongTheRow) {
  constexpr int n = 40;
  const glm::dvec3 a(0, 0, 0), b(10, -1.8, 0), c(10, 1.8, 0);
  std::vector<glm::dvec3> positions;
  std::vector<std::vector<int>> faces;
  std::vector<std::vector<int>> index(n + 1, std::vector<int>(n + 1, -1));
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j) {
      index[i][j] = int(positions.size());
      positions.push_back(a + (double(i) / n) * (b - a) + (double(j) / n) * (c - a));
    }
  for (int i = 0; i < n; ++i)
    for (int j = 0; i + j < n; ++j) {
      faces.push_back({index[i][j], index[i + 1][j], index[i][j + 1]});
      if (i + j + 1 < n) faces.push_back({index[i + 1][j], index[i + 1][j + 1], index[i][j + 1]});
    }
  const SurfaceMap map = build_surface_map(make_surface(positions, faces, "sharp tip").mesh);
  for (const double spacing : {0.3, 0.45}) {
    Design design;
    design.pattern.tessellation = Tessellation::Triangle;
    design.pattern.spacing = spacing;
    design.elements.rim_rows = RimRows::All;
    const Pavement p = make_pavement(map, design);
    EXPECT_EQ(p.rim_rows.loops, 1);
    // The outline is 23.9 long; the row runs inside it, short of the tip.
    EXPECT_GT(p.rim_rows.placed, int(0.7 * 23.9 / spacing)) << "D " << spacing;
    const test::AllPairs truth = test::all_pairs(p.elements, 0);
    EXPECT_EQ(truth.violations, 0) << "D " << spacing << ": smallest clearance " << truth.min_clearance;
    EXPECT_EQ(p.after.boundary_crossings, 0) << "D " << spacing;
  }
}

TEST(RimRows, AClosedSurfacesSeamsAreNoRims) {
  const auto map = test::bundled_map("bead");
  EXPECT_TRUE(rim_row_loops(*map, RimRows::All).empty());
  const Pavement p = make_pavement(*map, design_for(*map, Tessellation::Hexagon, RimRows::All, 0));
  EXPECT_EQ(p.rim_rows.placed, 0);
}

}  // namespace
}  // namespace paver
