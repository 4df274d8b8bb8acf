// The metal of a curved pendant with its seats cut (issue 14: "on a curved pendant"), checked point
// by point against what it must be: inside the cut solid exactly where a point is inside the
// thickened shell and inside no seat. The seats are tested analytically (a point's radius against
// the seat profile at its height in the stone's frame), the meshes by CGAL's inside test.
#include "cut/seat_cutter.h"
#include "cut/solid_cut.h"
#include "cut/thick_shell.h"

#include "closed_mesh_checks.h"
#include "elements/element_frame.h"
#include "pipeline/pavement.h"
#include "surface_maps.h"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include <random>

namespace paver {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;

Mesh to_mesh(const SurfaceMesh& m) {
  Mesh out;
  std::vector<Mesh::Vertex_index> v;
  for (const glm::dvec3& p : m.positions) v.push_back(out.add_vertex(K::Point_3(p.x, p.y, p.z)));
  for (const glm::ivec3& t : m.triangles) out.add_face(v[std::size_t(t.x)], v[std::size_t(t.y)], v[std::size_t(t.z)]);
  return out;
}

// How far inside (> 0) or outside (< 0) the seat of a stone a point is, radially, in units of d;
// the polygonal seat lies between its circumscribed circle and cos(pi/32) of it, so points within
// 1% of d of the wall are too close to call.
double seat_margin(const std::vector<glm::dvec2>& profile, const ElementFrame& f, const glm::dvec3& centre, double d,
                   const glm::dvec3& p) {
  const glm::dvec3 r = (p - centre) / d;
  const double z = glm::dot(r, f.n);
  const double radial = std::hypot(glm::dot(r, f.t), glm::dot(r, f.b));
  if (z > profile.front().y || z < profile.back().y) return -1;
  for (std::size_t i = 0; i + 1 < profile.size(); ++i) {
    const glm::dvec2 a = profile[i], b = profile[i + 1];
    if (z <= a.y && z >= b.y) {
      const double wall = a.y == b.y ? std::max(a.x, b.x) : b.x + (a.x - b.x) * (z - b.y) / (a.y - b.y);
      return wall - radial;
    }
  }
  return -1;
}

TEST(PendantCut, EveryPointIsMetalExactlyWhereTheShellIsAndNoSeatIs) {
  Design design;
  design.pattern.tessellation = Tessellation::Triangle;
  design.elements.gap = 0.1;
  set_stone_size(design, 1.5);
  PavementOptions options;
  options.threads = 1;
  const SurfaceMap& map = *test::bundled_map("pendant");
  const Pavement pavement = make_pavement(map, design, options);
  const Elements& stones = pavement.elements;
  ASSERT_GT(stones.size(), 300u);
  const double thickness = 1;
  const CutSolid cut = cut_pavement(map, stones, {.cutter = CutterKind::Seat, .thickness = thickness});
  EXPECT_EQ(test::unpaired_edges(cut.mesh), 0u);
  EXPECT_EQ(test::printed_3mf_problems(cut.mesh).merged_vertices, 0u) << "as cut.3mf prints it";
  EXPECT_EQ(test::printed_3mf_problems(cut.mesh).zero_area_triangles, 0u);
  EXPECT_NEAR(test::signed_volume(cut.mesh), cut.volume, 1e-9 * cut.volume);

  const Mesh shell = to_mesh(thick_shell(map.mesh, map.normals, thickness));
  const Mesh solid = to_mesh(cut.mesh);
  const CGAL::Side_of_triangle_mesh<Mesh, K> inside_shell(shell), inside_solid(solid);
  glm::dvec3 lo(1e300), hi(-1e300);
  for (const glm::dvec3& p : cut.mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);

  std::vector<std::vector<glm::dvec2>> profiles;
  std::vector<ElementFrame> frames;
  for (std::size_t s = 0; s < stones.size(); ++s) {
    profiles.push_back(seat_profile(cutter_reach_above(), cutter_reach_below(thickness, stones.diameter[s])));
    frames.push_back(element_frame(stones.normal[s]));
  }
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> x(lo.x, hi.x), y(lo.y, hi.y), z(lo.z, hi.z);
  int checked = 0, in_metal = 0, wrong = 0;
  for (int k = 0; k < 20000; ++k) {
    const glm::dvec3 p(x(rng), y(rng), z(rng));
    const K::Point_3 q(p.x, p.y, p.z);
    const CGAL::Bounded_side shell_side = inside_shell(q), solid_side = inside_solid(q);
    if (shell_side == CGAL::ON_BOUNDARY || solid_side == CGAL::ON_BOUNDARY) continue;
    bool in_seat = false, undecided = false;
    for (std::size_t s = 0; s < stones.size() && !in_seat; ++s) {
      if (glm::length(p - stones.position[s]) > stones.diameter[s] * (1 + profiles[s].back().y * -1)) continue;
      const double margin = seat_margin(profiles[s], frames[s], stones.position[s], stones.diameter[s], p);
      if (std::abs(margin) < 0.01) undecided = true;
      if (margin > 0.01) in_seat = true;
    }
    if (undecided && !in_seat) continue;
    const bool expected = shell_side == CGAL::ON_BOUNDED_SIDE && !in_seat;
    const bool got = solid_side == CGAL::ON_BOUNDED_SIDE;
    ++checked;
    in_metal += got;
    wrong += expected != got;
  }
  EXPECT_GT(checked, 15000);
  EXPECT_GT(in_metal, 500) << "enough points fell in the metal to mean something";
  EXPECT_EQ(wrong, 0) << "of " << checked << " points";
}

}  // namespace
}  // namespace paver
