#include "map/surface_charts.h"

#include "core/input_error.h"
#include "core/printable.h"
#include "map/bijective_map.h"
#include "map/map_quality.h"
#include "mesh/mean_curvature.h"
#include "mesh/mesh_repair.h"
#include "mesh/triangle_geometry.h"

#include <Eigen/Dense>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>

namespace paver {

namespace {

glm::dvec3 face_centroid(const SurfaceMesh& mesh, const glm::ivec3& t) {
  return (mesh.positions[t.x] + mesh.positions[t.y] + mesh.positions[t.z]) / 3.0;
}

// Smallest index of each face's connected piece among faces with the same side.
std::vector<int> pieces_by_side(const SurfaceMesh& mesh, const std::vector<int>& side) {
  const int nf = mesh.face_count();
  std::vector<int> parent(nf);
  std::iota(parent.begin(), parent.end(), 0);
  const auto find = [&](int f) {
    while (parent[f] != f) f = parent[f] = parent[parent[f]];
    return f;
  };
  std::map<std::pair<int, int>, int> first_face_of_edge;
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) {
      const auto key = std::minmax(mesh.triangles[f][k], mesh.triangles[f][(k + 1) % 3]);
      const auto [it, added] = first_face_of_edge.emplace(key, f);
      if (added || side[it->second] != side[f]) continue;
      const int a = find(it->second), b = find(f);
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  std::vector<int> piece(nf);
  for (int f = 0; f < nf; ++f) piece[f] = find(f);
  return piece;
}

// A crossing nearer a vertex than this share of its edge goes through the vertex instead: the
// seam then leaves the plane by at most that much, and no sliver is made.
constexpr double kSnapShare = 0.15;

struct SplitSurface {
  SurfaceMesh mesh;
  std::vector<int> face_side;  // 1 above the plane, 0 below
};

// The closed surface with every face that the plane crosses split along it, so that the seam is
// the plane's section (straight across the faces) and not a staircase of whole faces, which would
// keep a strip of elements off it as deep as a face. Vertices within kSnapShare of a crossing
// are taken as on the plane (not moved); each face's side is that of its vertices off the plane,
// of which no face has both kinds.
SplitSurface split_along_plane(const SurfaceMesh& closed, glm::dvec3 normal, double offset) {
  const int nv = closed.vertex_count();
  std::vector<double> height(nv);
  for (int v = 0; v < nv; ++v) height[v] = glm::dot(normal, closed.positions[v]) - offset;
  std::vector<int> side(nv);
  for (int v = 0; v < nv; ++v) side[v] = height[v] > 0 ? 1 : height[v] < 0 ? -1 : 0;
  for (const glm::ivec3& t : closed.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      if (side[a] * side[b] >= 0) continue;
      const double share = height[a] / (height[a] - height[b]);
      if (share < kSnapShare) side[a] = 0;
      if (share > 1 - kSnapShare) side[b] = 0;
    }
  std::vector<glm::dvec3> positions = closed.positions;
  std::map<std::pair<int, int>, int> crossing;
  const auto crossing_vertex = [&](int a, int b) {
    const auto key = std::minmax(a, b);
    const auto [it, added] = crossing.emplace(key, int(positions.size()));
    if (added) {
      const double share = height[a] / (height[a] - height[b]);
      positions.push_back(closed.positions[a] + share * (closed.positions[b] - closed.positions[a]));
    }
    return it->second;
  };
  SplitSurface out;
  std::vector<glm::ivec3>& faces = out.mesh.triangles;
  // Each side's part of a split triangle is a triangle or a convex quad, in the triangle's order.
  const auto add_part = [&](const std::vector<int>& part, int face_side) {
    if (part.size() == 3) {
      faces.emplace_back(part[0], part[1], part[2]);
      out.face_side.push_back(face_side);
    } else if (part.size() == 4) {
      // The shorter diagonal.
      const double d02 = glm::length(positions[part[0]] - positions[part[2]]);
      const double d13 = glm::length(positions[part[1]] - positions[part[3]]);
      if (d02 <= d13)
        faces.emplace_back(part[0], part[1], part[2]), faces.emplace_back(part[0], part[2], part[3]);
      else
        faces.emplace_back(part[1], part[2], part[3]), faces.emplace_back(part[1], part[3], part[0]);
      out.face_side.insert(out.face_side.end(), 2, face_side);
    }
  };
  for (const glm::ivec3& t : closed.triangles) {
    bool above = false, below = false;
    for (int k = 0; k < 3; ++k) above |= side[t[k]] > 0, below |= side[t[k]] < 0;
    if (!(above && below)) {
      faces.push_back(t);
      // A face with every vertex on the plane goes by its centroid.
      const double centroid = height[t.x] + height[t.y] + height[t.z];
      out.face_side.push_back(above || (!below && centroid >= 0) ? 1 : 0);
      continue;
    }
    std::vector<int> upper, lower;
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      if (side[a] >= 0) upper.push_back(a);
      if (side[a] <= 0) lower.push_back(a);
      if (side[a] * side[b] < 0) {
        const int x = crossing_vertex(a, b);
        upper.push_back(x), lower.push_back(x);
      }
    }
    add_part(upper, 1), add_part(lower, 0);
  }
  // The split keeps the closed surface closed, manifold and oriented: no repair to run.
  out.mesh.positions = std::move(positions);
  return out;
}

}  // namespace

namespace {

// The closed surface split across the plane dot(normal, p) = offset, each piece checked as an open
// surface (check_and_repair, which throws InputError naming the chart when a piece has handles).
ChartCut cut_across(const SurfaceMesh& closed, glm::dvec3 normal, double offset, const std::string& axis_name,
                    const std::string& source) {
  ChartCut cut;
  cut.normal = normal;
  cut.offset = offset;
  SplitSurface split = split_along_plane(closed, cut.normal, cut.offset);
  cut.surface = std::move(split.mesh);
  const SurfaceMesh& surface = cut.surface;
  const std::vector<int>& side = split.face_side;
  const std::vector<int> piece = pieces_by_side(surface, side);
  std::map<int, std::vector<int>> faces_of_piece;
  for (int f = 0; f < surface.face_count(); ++f) faces_of_piece[piece[f]].push_back(f);
  if (faces_of_piece.size() < 2)
    throw InputError(source + ": the plane across its " + axis_name +
                     " leaves all of the closed surface on one side; choose another --cut axis");

  for (const auto& [first, faces] : faces_of_piece) {
    std::vector<int> index(surface.vertex_count(), -1), vertex_of;
    std::vector<glm::dvec3> positions;
    std::vector<std::vector<int>> polygons;
    for (const int f : faces) {
      std::vector<int>& polygon = polygons.emplace_back();
      for (int k = 0; k < 3; ++k) {
        const int v = surface.triangles[f][k];
        if (index[v] < 0) {
          index[v] = int(positions.size());
          positions.push_back(surface.positions[v]);
          vertex_of.push_back(v);
        }
        polygon.push_back(index[v]);
      }
    }
    const std::string chart_name = source + " (chart " + std::to_string(cut.charts.size() + 1) +
                                   " of the closed surface cut across its " + axis_name + ")";
    // The chart's vertices must stay those of vertex_of: no joining, no splitting (a chart that
    // pinches at a vertex on the plane is refused as non-manifold, and another axis tried).
    LoadedSurface chart = check_and_repair(std::move(positions), polygons, chart_name, 0, VertexRepair::None);
    if (chart.mesh.vertex_count() != int(vertex_of.size()))
      throw InputError(chart_name + ": the cut left vertices no face of the chart uses; choose another --cut axis");
    cut.charts.push_back(std::move(chart.mesh));
    cut.vertex_of.push_back(std::move(vertex_of));
  }
  return cut;
}

}  // namespace

long long closed_surface_handles(long long vertices, long long faces) { return (2 - vertices + faces / 2) / 2; }

long long closed_surface_handles(const SurfaceMesh& closed) {
  return closed_surface_handles(closed.vertex_count(), closed.face_count());
}

bool cuts_into_charts(const SurfaceMesh& closed, CutAxis axis) {
  if (closed_surface_handles(closed) == 0) return true;
  try {
    cut_into_charts(closed, axis, "");
    return true;
  } catch (const InputError&) {
    return false;
  }
}

ChartCut cut_into_charts(const SurfaceMesh& closed, CutAxis axis, const std::string& source) {
  // The area centroid and, for the automatic axis, the principal axes of the area.
  const int nf = closed.face_count();
  std::vector<double> face_area(nf);
  double area = 0;
  glm::dvec3 centre(0);
  for (int f = 0; f < nf; ++f) {
    const glm::ivec3 t = closed.triangles[f];
    face_area[f] = detail::triangle_area(closed.positions[t.x], closed.positions[t.y], closed.positions[t.z]);
    area += face_area[f];
    centre += face_area[f] * face_centroid(closed, t);
  }
  centre /= area;
  if (axis != CutAxis::Auto) {
    const glm::dvec3 normal =
        axis == CutAxis::X ? glm::dvec3(1, 0, 0) : axis == CutAxis::Y ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, 1);
    return cut_across(closed, normal, glm::dot(normal, centre), std::string(enum_name(axis)) + " axis", source);
  }
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (int f = 0; f < nf; ++f) {
    const glm::dvec3 d = face_centroid(closed, closed.triangles[f]) - centre;
    const Eigen::Vector3d e(d.x, d.y, d.z);
    covariance += face_area[f] * e * e.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  const auto principal = [&](int k) {  // eigenvalues ascend: 2 is the longest axis, 0 the shortest
    const Eigen::Vector3d a = solver.eigenvectors().col(k);
    return glm::normalize(glm::dvec3(a.x(), a.y(), a.z()));
  };
  const long long handles = closed_surface_handles(closed);
  if (handles == 0) return cut_across(closed, principal(2), glm::dot(principal(2), centre), "longest axis", source);
  // A surface with handles (a solid ring, a pretzel) is cut where the plane runs through all of
  // them: across its shortest axis first (a ring lying flat, cut into its upper and lower halves,
  // two bands), then the others; the first plane whose charts have no handles is taken.
  const char* names[3] = {"shortest axis", "middle axis", "longest axis"};
  std::string last_error;
  for (int k = 0; k < 3; ++k) {
    try {
      return cut_across(closed, principal(k), glm::dot(principal(k), centre), names[k], source);
    } catch (const InputError& e) {
      last_error = e.what();
    }
  }
  throw InputError(source + ": has " + std::to_string(handles) + (handles == 1 ? " handle" : " handles") +
                   " and no plane across its three axes cuts through all of them (" + printable_cut(last_error) +
                   "); cut it into pieces without handles in the modelling tool");
}

std::optional<SurfaceMap> map_closed_surface(const SurfaceMesh& closed, CutAxis axis, const std::string& source,
                                             const std::function<void(int chart, int charts)>& progress,
                                             const std::function<bool()>& stop) {
  const ChartCut cut = cut_into_charts(closed, axis, source);
  const int charts = int(cut.charts.size());
  std::vector<Parameterization> maps;
  for (int c = 0; c < charts; ++c) {
    if (stop && stop()) return std::nullopt;
    if (progress) progress(c, charts);
    maps.push_back(parameterize_surface(cut.charts[c], map_options_for(cut.charts[c], MapPiece::Chart)));
  }

  // Side by side along u, centred on v = 0, half the largest chart apart: no lattice edge spans two.
  std::vector<glm::dvec2> lo(charts), hi(charts);
  double largest = 0;
  for (int c = 0; c < charts; ++c) {
    lo[c] = glm::dvec2(std::numeric_limits<double>::infinity()), hi[c] = -lo[c];
    for (const glm::dvec2& q : maps[c].uv) lo[c] = glm::min(lo[c], q), hi[c] = glm::max(hi[c], q);
    largest = std::max({largest, hi[c].x - lo[c].x, hi[c].y - lo[c].y});
  }
  SurfaceMesh atlas;
  std::vector<glm::dvec2> uv;
  std::vector<int> surface_vertex, chart_of_face;
  double cursor = 0;
  for (int c = 0; c < charts; ++c) {
    const int base = atlas.vertex_count();
    const glm::dvec2 shift(cursor - lo[c].x, -0.5 * (lo[c].y + hi[c].y));
    for (int v = 0; v < cut.charts[c].vertex_count(); ++v) {
      atlas.positions.push_back(cut.charts[c].positions[v]);
      uv.push_back(maps[c].uv[v] + shift);
      surface_vertex.push_back(cut.vertex_of[c][v]);
    }
    for (const glm::ivec3& t : cut.charts[c].triangles) {
      atlas.triangles.push_back(t + glm::ivec3(base));
      chart_of_face.push_back(c);
    }
    for (const std::vector<int>& loop : cut.charts[c].boundary_loops) {
      std::vector<int>& kept = atlas.boundary_loops.emplace_back();
      for (const int v : loop) kept.push_back(v + base);
    }
    cursor += hi[c].x - lo[c].x + 0.5 * largest;
  }

  Parameterization combined;
  combined.uv = uv;
  combined.quality = measure_map(atlas, uv);
  combined.report = maps.front().report;
  for (int c = 1; c < charts; ++c) {
    combined.report.iterations += maps[c].report.iterations;
    combined.report.blocked_steps += maps[c].report.blocked_steps;
    combined.report.factorizations += maps[c].report.factorizations;
    combined.report.precompute_ms += maps[c].report.precompute_ms;
    combined.report.solve_ms += maps[c].report.solve_ms;
  }
  SurfaceMap map = make_surface_map(std::move(atlas), std::move(combined));
  map.seamless_unavailable.clear();  // two charts' seams are not a band's rims
  // Normals and curvature of the closed surface: a seam vertex has faces on both sides.
  const std::vector<glm::dvec3> normals = vertex_normals(cut.surface);
  const std::vector<double> curvature = mean_curvature(cut.surface);
  for (std::size_t v = 0; v < surface_vertex.size(); ++v) {
    map.normals[v] = normals[surface_vertex[v]];
    map.curvature[v] = curvature[surface_vertex[v]];
  }
  set_curvature_range(map);
  map.chart_of_face = std::move(chart_of_face);
  map.closed_surface_vertices = closed.vertex_count();
  map.closed_surface_faces = closed.face_count();
  map.closed_surface = cut.surface;
  map.cut_normal = cut.normal;
  map.closed_surface_normals = normals;
  return map;
}

}  // namespace paver
