#include "mesh_checks.h"

#include "core/input_error.h"
#include "mesh/mesh_loader.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace paver::assetgen {
namespace {

using glm::dvec3;

constexpr double kPi = glm::pi<double>();

// Quality floor every generated surface must meet (degrees).
constexpr double kMinAngleDeg = 20.0;

[[noreturn]] void fail(std::string_view name, const std::string& why) {
  throw std::runtime_error(std::string(name) + ": " + why);
}

// The engine's checks, the ones a user's surface gets. Bundled assets must come out clean, so a
// repair (its warnings) fails too, and so does any change to the faces.
SurfaceMesh checked_topology(std::string_view name, const Mesh& m) {
  std::vector<std::vector<int>> polygons;
  polygons.reserve(m.f.size());
  for (const auto& t : m.f) polygons.push_back({t[0], t[1], t[2]});
  LoadedSurface loaded;
  try {
    loaded = make_surface(m.v, polygons, std::string(name));
  } catch (const InputError& e) {
    throw std::runtime_error(e.what());  // already starts with the name
  }
  if (!loaded.warnings.empty()) {
    std::string all = loaded.warnings.front();
    for (std::size_t i = 1; i < loaded.warnings.size(); ++i) all += "; " + loaded.warnings[i];
    throw std::runtime_error(all + " (a bundled surface must need no repair)");
  }
  bool same = loaded.mesh.positions.size() == m.v.size() && loaded.mesh.triangles.size() == m.f.size();
  for (std::size_t i = 0; same && i < m.f.size(); ++i)
    same = loaded.mesh.triangles[i] == glm::ivec3(m.f[i][0], m.f[i][1], m.f[i][2]);
  if (!same) fail(name, "make_surface changed the mesh without a warning");
  return std::move(loaded.mesh);
}

}  // namespace

Stats check(std::string_view name, const Mesh& m, const Outward& outward, int boundary_loops) {
  const SurfaceMesh mesh = checked_topology(name, m);
  if (int(mesh.boundary_loops.size()) != boundary_loops)
    fail(name, "has " + std::to_string(mesh.boundary_loops.size()) + " boundary loops, not " +
                   std::to_string(boundary_loops));
  Stats s;
  s.vertices = mesh.vertex_count();
  s.faces = mesh.face_count();
  s.lo = s.hi = m.v.front();
  for (const dvec3& p : m.v) {
    s.lo = glm::min(s.lo, p);
    s.hi = glm::max(s.hi, p);
  }
  // Every interior edge is a side of two faces and every boundary edge of one face and of the
  // boundary loop, so the sums below count each edge twice.
  double sum = 0.0;
  double sum2 = 0.0;
  const auto add_edge = [&](int a, int b) {
    const double len = glm::distance(m.v[a], m.v[b]);
    sum += len;
    sum2 += len * len;
  };
  for (std::size_t fi = 0; fi < m.f.size(); ++fi) {
    const auto& t = m.f[fi];
    if (glm::dot(face_normal(m, t), outward(centroid(m, t))) <= 0.0)
      fail(name, "face " + std::to_string(fi) + " points inward");
    for (int c = 0; c < 3; ++c) {
      add_edge(t[c], t[(c + 1) % 3]);
      const dvec3 e1 = glm::normalize(m.v[t[(c + 1) % 3]] - m.v[t[c]]);
      const dvec3 e2 = glm::normalize(m.v[t[(c + 2) % 3]] - m.v[t[c]]);
      const double angle = std::acos(std::clamp(glm::dot(e1, e2), -1.0, 1.0)) * 180.0 / kPi;
      s.min_angle_deg = std::min(s.min_angle_deg, angle);
    }
  }
  const std::vector<glm::ivec2> boundary = boundary_segments(mesh);
  for (const glm::ivec2& segment : boundary) add_edge(segment.x, segment.y);
  if (!(s.min_angle_deg >= kMinAngleDeg))
    fail(name, "minimum angle " + std::to_string(s.min_angle_deg) + " degrees is below the floor of " +
                   std::to_string(kMinAngleDeg));
  const double edges = 0.5 * static_cast<double>(3 * m.f.size() + boundary.size());
  s.edge_mean = 0.5 * sum / edges;
  s.edge_cv = std::sqrt(std::max(0.0, 0.5 * sum2 / edges - s.edge_mean * s.edge_mean)) / s.edge_mean;
  return s;
}

}  // namespace paver::assetgen
