#include "cut/solid_cut.h"

#include "core/input_error.h"
#include "core/interrupted.h"
#include "core/number_text.h"
#include "core/stopwatch.h"
#include "cut/thick_shell.h"
#include "elements/element_frame.h"
#include "io/shape_table.h"

#include <glm/geometric.hpp>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/intersection.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Polygon_mesh_processing/repair_self_intersections.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace paver {
namespace {

// The boolean constructs new points: exactly (Epeck). The checks run on the result rounded to
// doubles, with exact predicates (Epick): that is the solid the files hold, and exact numbers
// would make them a hundred times slower.
using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using RoundedMesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

template <class MeshType = Mesh>
MeshType to_cgal(const SurfaceMesh& m) {
  using P = typename MeshType::Point;
  MeshType out;
  std::vector<typename MeshType::Vertex_index> vertices;
  vertices.reserve(m.positions.size());
  for (const glm::dvec3& p : m.positions) vertices.push_back(out.add_vertex(P(p.x, p.y, p.z)));
  for (const glm::ivec3& t : m.triangles)
    if (out.add_face(vertices[std::size_t(t.x)], vertices[std::size_t(t.y)], vertices[std::size_t(t.z)]) ==
        MeshType::null_face())
      throw std::runtime_error("cut: a mesh is not a manifold surface (a face could not be added)");
  return out;
}

// The boolean's exact points as the files hold them: corners that round to the same point become
// one vertex, a triangle left with two equal corners goes, and so do two triangles left on the
// same three corners facing apart. The checks then run on this, the solid that is written.
// Rounded to a millionth of a unit first, then to float32: lib3mf writes 3MF coordinates with six
// decimals, so two float32 corners a nanometre apart became one point in cut.3mf and left zero-area
// triangles there (6 to 58 per jeweller's job) though cut.stl had none. A millionth is below
// float32's own step beyond 8 units, and at most half of it below.
SurfaceMesh from_cgal(const Mesh& m) {
  const auto snap = [](const auto& c) { return float(std::round(CGAL::to_double(c) * 1e6) / 1e6); };
  SurfaceMesh out;
  std::map<std::array<float, 3>, int> welded;
  std::unordered_map<std::size_t, int> index;
  for (const Mesh::Vertex_index v : m.vertices()) {
    const Point& p = m.point(v);
    const std::array<float, 3> rounded = {snap(p.x()), snap(p.y()), snap(p.z())};
    const auto [it, added] = welded.emplace(rounded, static_cast<int>(out.positions.size()));
    if (added) out.positions.emplace_back(rounded[0], rounded[1], rounded[2]);
    index[std::size_t(v)] = it->second;
  }
  std::map<std::array<int, 3>, std::vector<std::size_t>> by_corners;  // sorted corners -> triangles
  for (const Mesh::Face_index f : m.faces()) {
    glm::ivec3 t;
    int k = 0;
    for (const Mesh::Vertex_index v : CGAL::vertices_around_face(m.halfedge(f), m)) {
      if (k < 3) t[k] = index.at(std::size_t(v));
      ++k;
    }
    if (k != 3) throw std::runtime_error("cut: the boolean returned a face that is not a triangle");
    if (t.x == t.y || t.y == t.z || t.z == t.x) continue;
    std::array<int, 3> key = {t.x, t.y, t.z};
    std::sort(key.begin(), key.end());
    by_corners[key].push_back(out.triangles.size());
    out.triangles.push_back(t);
  }
  std::vector<bool> drop(out.triangles.size(), false);
  for (const auto& [corners, triangles] : by_corners)
    if (triangles.size() == 2) drop[triangles[0]] = drop[triangles[1]] = true;
  std::size_t kept = 0;
  for (std::size_t i = 0; i < out.triangles.size(); ++i)
    if (!drop[i]) out.triangles[kept++] = out.triangles[i];
  out.triangles.resize(kept);
  return out;
}

SurfaceMesh from_rounded(const RoundedMesh& m) {
  SurfaceMesh out;
  std::unordered_map<std::size_t, int> index;
  for (const RoundedMesh::Vertex_index v : m.vertices()) {
    index[std::size_t(v)] = static_cast<int>(out.positions.size());
    out.positions.emplace_back(m.point(v).x(), m.point(v).y(), m.point(v).z());
  }
  for (const RoundedMesh::Face_index f : m.faces()) {
    glm::ivec3 t;
    int k = 0;
    for (const RoundedMesh::Vertex_index v : CGAL::vertices_around_face(m.halfedge(f), m))
      if (k < 3) t[k++] = index.at(std::size_t(v));
    out.triangles.push_back(t);
  }
  return out;
}

// By the divergence theorem, in doubles.
double volume_of(const SurfaceMesh& m) {
  double six_v = 0;
  for (const glm::ivec3& t : m.triangles)
    six_v += glm::dot(m.positions[std::size_t(t.x)],
                      glm::cross(m.positions[std::size_t(t.y)], m.positions[std::size_t(t.z)]));
  return six_v / 6;
}

struct DisjointSets {
  explicit DisjointSets(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), std::size_t{0}); }
  std::size_t find(std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void unite(std::size_t a, std::size_t b) { parent[find(a)] = find(b); }
  std::vector<std::size_t> parent;
};

// One mesh of the `parts` (closed solids, part i within `reach` of `centres[i]`): those that
// touch are found among near neighbours and united cluster by cluster, and the clusters,
// disjoint, are joined as one mesh of separate closed parts. `united` counts the parts that
// touched another.
template <class CheckStop>
Mesh merge_solids(std::vector<Mesh>& parts, const std::vector<glm::dvec3>& centres, double reach,
                  const CheckStop& check_stop, int& united) {
  const std::size_t n = parts.size();
  // Two parts can touch only when their centres are within 2 reach: cells that wide put them in
  // neighbouring cells.
  const double widest = 2 * reach > 0 ? 2 * reach : 1.0;
  DisjointSets sets(n);
  std::map<std::array<long, 3>, std::vector<std::size_t>> cells;
  const auto cell_of = [&](const glm::dvec3& p) {
    return std::array<long, 3>{long(std::floor(p.x / widest)), long(std::floor(p.y / widest)),
                               long(std::floor(p.z / widest))};
  };
  for (std::size_t i = 0; i < n; ++i) cells[cell_of(centres[i])].push_back(i);
  for (std::size_t i = 0; i < n; ++i) {
    const auto c = cell_of(centres[i]);
    for (long dx = -1; dx <= 1; ++dx)
      for (long dy = -1; dy <= 1; ++dy)
        for (long dz = -1; dz <= 1; ++dz) {
          const auto it = cells.find({c[0] + dx, c[1] + dy, c[2] + dz});
          if (it == cells.end()) continue;
          for (const std::size_t j : it->second)
            if (j > i && sets.find(i) != sets.find(j) && PMP::do_intersect(parts[i], parts[j])) sets.unite(i, j);
        }
    if ((i & 63) == 0) check_stop();
  }
  std::map<std::size_t, std::vector<std::size_t>> clusters;
  for (std::size_t i = 0; i < n; ++i) clusters[sets.find(i)].push_back(i);
  Mesh all;
  for (auto& [root, members] : clusters) {
    Mesh cluster = parts[members[0]];
    for (std::size_t k = 1; k < members.size(); ++k) {
      Mesh next;
      if (!PMP::corefine_and_compute_union(cluster, parts[members[k]], next))
        throw std::runtime_error("cut: uniting two touching solids failed (number " + std::to_string(members[k]) + ")");
      cluster = std::move(next);
      check_stop();
    }
    if (members.size() > 1) united += static_cast<int>(members.size());
    all += cluster;
  }
  return all;
}

// A unit-diameter cutter placed on an element, as the element's own shape sits (elements/element_frame.h).
SurfaceMesh placed_cutter(const SurfaceMesh& unit, const glm::dvec3& centre, const glm::dvec3& normal, double diameter) {
  const ElementFrame frame = element_frame(normal);
  SurfaceMesh m = unit;
  for (glm::dvec3& p : m.positions) p = place_shape_vertex(frame, centre, diameter, p);
  return m;
}

}  // namespace

double cutter_reach_above() { return 0.6; }

double cutter_reach_below(double thickness, double diameter) { return 1.5 * thickness / diameter + 0.5; }

double estimated_cut_bytes(const Elements& elements, const CutOptions& options) {
  const ShapeTable shapes(elements, options.custom, "cut");
  const double seat = double(unit_cutter(CutterKind::Seat, make_builtin_shape(ShapeKind::Gem), cutter_reach_above(),
                                         cutter_reach_below(1, 1))
                                 .triangles.size());
  std::array<double, ShapeTable::kKinds> per_shape;
  per_shape.fill(-1);
  double cutters = 0;  // in seat cutters
  for (std::size_t i = 0; i < elements.size(); ++i) {
    double& share = per_shape[static_cast<std::size_t>(elements.shape[i])];
    if (share < 0)
      share = double(unit_cutter(options.cutter, shapes[elements.shape[i]], cutter_reach_above(), cutter_reach_below(1, 1))
                         .triangles.size()) /
              seat;
    cutters += share;
  }
  if (options.beads && options.beads->size() > 0)
    cutters += double(options.beads->size()) *
               double(unit_cutter(CutterKind::Element, make_builtin_shape(ShapeKind::Sphere), 0, 0).triangles.size()) / seat;
  return cutters * kCutBytesPerSeatCutter;
}

void refuse_cut_beyond_memory(const Elements& elements, const CutOptions& options, double available_bytes) {
  const double bytes = estimated_cut_bytes(elements, options), usable = kCutMemoryShare * available_bytes;
  if (bytes <= usable) return;
  char text[320];
  std::snprintf(text, sizeof text,
                "--subtract: cutting %zu seats%s would take about %.1f GB (about 0.5 GB a thousand, measured), more "
                "than the %.1f GB this machine has free for it; use fewer or larger stones, or cut the piece in parts",
                elements.size(), options.beads && options.beads->size() > 0 ? " and joining the beads" : "", bytes / 1e9,
                usable / 1e9);
  throw InputError(text);
}

CutSolid cut_pavement(const SurfaceMap& map, const Elements& paved, const CutOptions& options) {
  const Stopwatch watch;
  const Elements elements = seated_stones(paved, options.seat_depth);
  const auto check_stop = [&] {
    if (options.stop && options.stop->load()) throw Interrupted();
  };
  CutSolid result;
  result.seat_depth = options.seat_depth;
  // A closed surface's metal is a hollow shell of the whole surface (its atlas's charts would each
  // get a wall at their seams).
  const bool closed = is_atlas(map);
  const FingerSide* ring = options.finger_side;
  const SurfaceMesh shell_mesh = ring ? ring_shell(map.mesh, *ring)
                                      : thick_shell(closed ? map.closed_surface : map.mesh,
                                                    closed ? map.closed_surface_normals : map.normals, options.thickness);
  // The seats' holes reach through the metal where it is thickest.
  const double deepest_metal = ring ? ring->thickest() : options.thickness;
  result.thinnest_metal = ring ? ring->thinnest() : options.thickness;
  result.thickest_metal = deepest_metal;
  result.inside_diameter = ring ? 2 * ring->inside_radius : 0;
  if (PMP::does_self_intersect(to_cgal<RoundedMesh>(shell_mesh)))
    throw InputError("--thickness " + number_text(options.thickness) +
                     ": the metal folds into itself (the surface curves more tightly than that somewhere); use a "
                     "thinner metal");
  result.shell_volume = volume_of(shell_mesh);
  Mesh shell = to_cgal(shell_mesh);

  // Each element's cutter, placed; those that touch are found among near neighbours only.
  const ShapeTable shapes(elements, options.custom, "cut");
  const std::size_t n = elements.size();
  std::vector<Mesh> cutters;
  cutters.reserve(n);
  double reach = 0;  // the farthest any cutter's point lies from its element's centre
  for (std::size_t i = 0; i < n; ++i) {
    const double d = elements.diameter[i];
    for (const glm::vec3& v : shapes[elements.shape[i]].positions)
      result.deepest_stone = std::max(result.deepest_stone, -double(v.z) * d + options.seat_depth);
    // A stone set deeper: its handle still reaches out past the metal's top face.
    const SurfaceMesh unit = unit_cutter(options.cutter, shapes[elements.shape[i]], cutter_reach_above() + options.seat_depth / d,
                                         cutter_reach_below(deepest_metal, d));
    for (const glm::dvec3& v : unit.positions) reach = std::max(reach, d * glm::length(v));
    cutters.push_back(to_cgal(placed_cutter(unit, elements.position[i], elements.normal[i], d)));
  }
  check_stop();
  Mesh all_cutters = merge_solids(cutters, elements.position, reach, check_stop, result.united_cutters);
  result.cutters = static_cast<int>(n);
  check_stop();

  Mesh cut;
  if (n == 0) {
    cut = shell;
  } else if (!PMP::corefine_and_compute_difference(shell, all_cutters, cut)) {
    throw std::runtime_error("cut: the difference of the metal and the cutters is not a manifold solid");
  }
  // Beads are metal: they join the cut solid, their lower halves inside it.
  if (options.beads && options.beads->size() > 0) {
    const Elements& beads = *options.beads;
    const SurfaceMesh unit = unit_cutter(CutterKind::Element, make_builtin_shape(ShapeKind::Sphere), 0, 0);
    std::vector<Mesh> spheres;
    double bead_reach = 0;
    for (std::size_t b = 0; b < beads.size(); ++b) {
      spheres.push_back(to_cgal(placed_cutter(unit, beads.position[b], beads.normal[b], beads.diameter[b])));
      bead_reach = std::max(bead_reach, 0.5 * beads.diameter[b]);
    }
    int united_beads = 0;
    Mesh all_beads = merge_solids(spheres, beads.position, bead_reach, check_stop, united_beads);
    Mesh joined;
    if (!PMP::corefine_and_compute_union(cut, all_beads, joined))
      throw std::runtime_error("cut: joining the beads to the metal did not give a manifold solid");
    cut = std::move(joined);
    result.beads = static_cast<int>(beads.size());
  }
  // Where a face meets a cutter's vertex exactly on its edge (a sphere's equator on a flat top),
  // the boolean can leave needle triangles of zero area; they are collapsed away.
  RoundedMesh rounded = to_cgal<RoundedMesh>(from_cgal(cut));
  PMP::remove_degenerate_faces(rounded);
  // Rounding can fold slivers where the boolean made points a few nanometres apart (a bead's
  // sphere meeting a seat): CGAL removes such faces and fills the holes again, locally.
  if (PMP::does_self_intersect(rounded)) PMP::experimental::remove_self_intersections(rounded);
  rounded.collect_garbage();
  result.mesh = from_rounded(rounded);
  if (!CGAL::is_closed(rounded)) throw std::runtime_error("cut: the result is not closed");
  if (!PMP::is_outward_oriented(rounded)) throw std::runtime_error("cut: the result is not outward-oriented");
  if (PMP::does_self_intersect(rounded)) throw std::runtime_error("cut: the result intersects itself");
  result.volume = volume_of(result.mesh);
  result.milliseconds = watch.milliseconds();
  return result;
}

}  // namespace paver
