// The stray pull-back's binned search (kernels::pull_back over the grid's boundary bins, the
// same walk as shaders/solver_lift.comp) against a scan of every segment: the same segment and the
// same nudged point, bit for bit, for points around, inside and far outside each map, near its
// corners and holes. The GPU's lavapipe parity tests then carry the equality to the shader.
#include "solver/solver_kernels.h"
#include "solver/solver_surface.h"
#include "surface_maps.h"

#include <glm/common.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace paver {
namespace {

struct Nearest {
  int segment = 0;
  glm::vec2 nudged{0};
};

// Every segment in index order, the first of the nearest winning: what pull_back did before the
// bins.
Nearest scan_every_segment(const SolverSurface& s, glm::vec2 p) {
  Nearest out;
  out.nudged = p;
  float best = INFINITY;
  for (int i = 0; i < int(s.boundary_segments.size()); ++i) {
    const glm::vec4 e = s.boundary_segments[std::size_t(i)];
    const BoundaryCandidate c = wrapped_boundary_candidate(s.period, p, glm::vec2(e.x, e.y), glm::vec2(e.z, e.w),
                                                           s.boundary_inward[std::size_t(i)]);
    if (c.dist2 < best) {
      best = c.dist2;
      out.segment = i;
      out.nudged = c.nudged;
    }
  }
  return out;
}

std::vector<glm::vec2> probe_points(const SolverSurface& s, std::mt19937& random) {
  glm::vec2 lo(INFINITY), hi(-INFINITY);
  for (const glm::vec2& q : s.uv) lo = glm::min(lo, q), hi = glm::max(hi, q);
  const glm::vec2 size = hi - lo;
  std::vector<glm::vec2> points;
  // Around the map, a third of its size beyond each side.
  std::uniform_real_distribution<float> u(lo.x - size.x / 3, hi.x + size.x / 3), v(lo.y - size.y / 3, hi.y + size.y / 3);
  for (int i = 0; i < 3000; ++i) points.emplace_back(u(random), v(random));
  // Far away, where the search must cover the whole grid.
  for (float k : {-20.0f, 20.0f}) points.emplace_back(lo.x + k * size.x, lo.y), points.emplace_back(lo.x, lo.y + k * size.y);
  // On and just outside every boundary vertex and segment middle: ties between neighbouring
  // segments and the nearest cell.
  for (std::size_t i = 0; i < s.boundary_segments.size(); ++i) {
    const glm::vec4 e = s.boundary_segments[i];
    const glm::vec2 a(e.x, e.y), b(e.z, e.w), middle = 0.5f * (a + b);
    const glm::vec2 outward = middle - s.boundary_inward[i];
    points.push_back(a);
    points.push_back(middle + 0.5f * outward);
    points.push_back(a + 0.01f * outward);
  }
  return points;
}

class PullBack : public ::testing::TestWithParam<std::string> {};

// A NaN point is never lifted (the solvers stop on one first), but the search must still end.
TEST(PullBackNaN, ANanPointEndsTheSearchAndComesBackAsItWas) {
  const SolverSurface s = make_solver_surface(*test::named_map("pendant"));
  for (const glm::vec2 p : {glm::vec2(NAN, 1.0f), glm::vec2(1.0f, NAN), glm::vec2(NAN, NAN)}) {
    int segment = 0;
    const glm::vec2 q = kernels::pull_back(s, p, segment);
    EXPECT_EQ(segment, 0);
    EXPECT_TRUE(std::isnan(q.x) || std::isnan(q.y));
  }
}

TEST_P(PullBack, BinnedSearchFindsWhatAFullScanFinds) {
  const SolverSurface s = make_solver_surface(*test::named_map(GetParam()));
  ASSERT_FALSE(s.boundary_segments.empty());
  ASSERT_EQ(s.boundary_grid_start.size(), std::size_t(s.grid_nx) * std::size_t(s.grid_ny) + 1);
  std::mt19937 random(7);
  int compared = 0;
  for (const glm::vec2 p : probe_points(s, random)) {
    const Nearest expected = scan_every_segment(s, p);
    int segment = 0;
    const glm::vec2 nudged = kernels::pull_back(s, p, segment);
    ASSERT_EQ(segment, expected.segment) << GetParam() << ": point (" << p.x << ", " << p.y << ")";
    ASSERT_EQ(nudged, expected.nudged) << GetParam() << ": point (" << p.x << ", " << p.y << ")";
    ++compared;
  }
  EXPECT_GT(compared, 3000);
}

INSTANTIATE_TEST_SUITE_P(Surfaces, PullBack,
                         ::testing::Values("pendant", "pendant_pierced", "facade_windows", "saddle", "wave", "vase",
                                           "bunnyhead", "bunnyhead_three_loops", "bangle"),
                         [](const auto& info) { return info.param; });

// The bins hold every segment in every cell its box overlaps (and one more around), once per cell.
TEST(PullBackBins, EverySegmentIsBinnedOncePerCellInOrder) {
  const SolverSurface s = make_solver_surface(*test::named_map("facade_windows"));
  // Every cell the segment's box overlaps (in double: the float cells may round either way, and
  // the bins' margin of one cell covers that) holds it.
  const auto holds = [&](int x, int y, int segment) {
    const int c = y * s.grid_nx + x;
    return std::binary_search(s.boundary_grid_segments.begin() + s.boundary_grid_start[std::size_t(c)],
                              s.boundary_grid_segments.begin() + s.boundary_grid_start[std::size_t(c) + 1], segment);
  };
  for (int i = 0; i < int(s.boundary_segments.size()); ++i) {
    const glm::vec4 e = s.boundary_segments[std::size_t(i)];
    const auto cell_of = [&](double value, double origin, int n) {
      return std::clamp(int(std::floor((value - origin) / s.grid_cell_size)), 0, n - 1);
    };
    for (int y = cell_of(std::min(e.y, e.w), s.grid_origin.y, s.grid_ny); y <= cell_of(std::max(e.y, e.w), s.grid_origin.y, s.grid_ny); ++y)
      for (int x = cell_of(std::min(e.x, e.z), s.grid_origin.x, s.grid_nx); x <= cell_of(std::max(e.x, e.z), s.grid_origin.x, s.grid_nx); ++x)
        ASSERT_TRUE(holds(x, y, i)) << "segment " << i << " is missing from cell (" << x << ", " << y << ")";
  }
  for (std::size_t c = 0; c + 1 < s.boundary_grid_start.size(); ++c) {
    EXPECT_LE(s.boundary_grid_start[c], s.boundary_grid_start[c + 1]);
    for (int k = s.boundary_grid_start[c] + 1; k < s.boundary_grid_start[c + 1]; ++k)
      EXPECT_LT(s.boundary_grid_segments[std::size_t(k - 1)], s.boundary_grid_segments[std::size_t(k)]) << "cell " << c;
  }
}

}  // namespace
}  // namespace paver
