#include "mesh_checks.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
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

std::uint64_t edge_key(int a, int b) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

}  // namespace

Stats check(std::string_view name, const Mesh& m, const Outward& outward) {
  const int nv = static_cast<int>(m.v.size());
  Stats s;
  s.vertices = nv;
  s.faces = static_cast<int>(m.f.size());

  std::vector<int> used(nv, 0);
  std::unordered_map<std::uint64_t, int> directed;  // directed edge -> face
  directed.reserve(m.f.size() * 3);
  for (std::size_t fi = 0; fi < m.f.size(); ++fi) {
    const auto& t = m.f[fi];
    for (int c = 0; c < 3; ++c) {
      if (t[c] < 0 || t[c] >= nv) fail(name, "face " + std::to_string(fi) + " has an invalid vertex index");
      ++used[t[c]];
    }
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0])
      fail(name, "face " + std::to_string(fi) + " repeats a vertex");
    for (int c = 0; c < 3; ++c) {
      // A directed edge used twice means an edge with more than two faces or two faces wound
      // against each other.
      if (!directed.emplace(edge_key(t[c], t[(c + 1) % 3]), static_cast<int>(fi)).second)
        fail(name, "edge " + std::to_string(t[c]) + "-" + std::to_string(t[(c + 1) % 3]) +
                       " is non-manifold or inconsistently oriented");
    }
  }
  for (int i = 0; i < nv; ++i)
    if (used[i] == 0) fail(name, "vertex " + std::to_string(i) + " is not used by any face");

  // Boundary edges: directed edges without a twin. Each boundary vertex must have exactly one
  // outgoing one, and following them must visit all of them in one loop.
  std::vector<int> next(nv, -1);
  int interior_halves = 0;
  for (const auto& [key, fi] : directed) {
    const int a = static_cast<int>(key >> 32);
    const int b = static_cast<int>(key & 0xffffffffu);
    if (directed.count(edge_key(b, a)) != 0) {
      ++interior_halves;
      continue;
    }
    if (next[a] != -1) fail(name, "vertex " + std::to_string(a) + " is pinched (two boundary edges leave it)");
    next[a] = b;
    ++s.boundary;
  }
  s.edges = interior_halves / 2 + s.boundary;
  if (s.boundary == 0) fail(name, "mesh has no boundary (closed surface)");
  const int start = static_cast<int>(std::find_if(next.begin(), next.end(), [](int x) { return x != -1; }) - next.begin());
  int loop = 0;
  for (int v = start;;) {
    v = next[v];
    ++loop;
    if (v == -1) fail(name, "boundary is not a closed loop");
    if (v == start) break;
    if (loop > s.boundary) fail(name, "boundary walk does not return to its start");
  }
  if (loop != s.boundary)
    fail(name, "boundary has more than one loop (" + std::to_string(loop) + " of " +
                   std::to_string(s.boundary) + " boundary edges in the first)");
  const int euler = s.vertices - s.edges + s.faces;
  if (euler != 1) fail(name, "Euler characteristic is " + std::to_string(euler) + ", expected 1");

  // Vertex links: the faces around a vertex must form a single fan (no pinched vertices).
  std::vector<std::vector<std::pair<int, int>>> link(nv);
  for (const auto& t : m.f)
    for (int c = 0; c < 3; ++c) link[t[c]].emplace_back(t[(c + 1) % 3], t[(c + 2) % 3]);
  for (int v = 0; v < nv; ++v) {
    const auto& l = link[v];
    const auto succ = [&l](int x) {
      for (const auto& [from, to] : l)
        if (from == x) return to;
      return -1;
    };
    int first = l.front().first;
    for (const auto& [from, to] : l) {
      const bool has_pred = std::any_of(l.begin(), l.end(), [from = from](const auto& e) { return e.second == from; });
      if (!has_pred) first = from;
    }
    std::size_t walked = 0;
    for (int x = first; walked <= l.size();) {
      x = succ(x);
      if (x == -1) break;
      ++walked;
      if (x == first) break;
    }
    if (walked != l.size()) fail(name, "vertex " + std::to_string(v) + " is non-manifold (faces around it form several fans)");
  }

  // Connectivity by union-find over face edges.
  std::vector<int> parent(nv);
  std::iota(parent.begin(), parent.end(), 0);
  const auto root = [&parent](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const auto& t : m.f)
    for (int c = 0; c < 3; ++c) parent[root(t[c])] = root(t[(c + 1) % 3]);
  for (int v = 0; v < nv; ++v)
    if (root(v) != root(0)) fail(name, "mesh is not connected");

  // Geometry: orientation, angles, edge lengths, bounding box.
  s.lo = s.hi = m.v.front();
  for (const dvec3& p : m.v) {
    s.lo = glm::min(s.lo, p);
    s.hi = glm::max(s.hi, p);
  }
  for (std::size_t fi = 0; fi < m.f.size(); ++fi) {
    const auto& t = m.f[fi];
    if (glm::dot(face_normal(m, t), outward(centroid(m, t))) <= 0.0)
      fail(name, "face " + std::to_string(fi) + " points inward");
    for (int c = 0; c < 3; ++c) {
      const dvec3 e1 = glm::normalize(m.v[t[(c + 1) % 3]] - m.v[t[c]]);
      const dvec3 e2 = glm::normalize(m.v[t[(c + 2) % 3]] - m.v[t[c]]);
      const double angle = std::acos(std::clamp(glm::dot(e1, e2), -1.0, 1.0)) * 180.0 / kPi;
      s.min_angle_deg = std::min(s.min_angle_deg, angle);
    }
  }
  if (!(s.min_angle_deg >= kMinAngleDeg))
    fail(name, "minimum angle " + std::to_string(s.min_angle_deg) + " degrees is below the floor of " +
                   std::to_string(kMinAngleDeg));
  double sum = 0.0;
  double sum2 = 0.0;
  for (const auto& [key, fi] : directed) {
    const int a = static_cast<int>(key >> 32);
    const int b = static_cast<int>(key & 0xffffffffu);
    if (a > b && directed.count(edge_key(b, a)) != 0) continue;  // count interior edges once
    const double len = glm::distance(m.v[a], m.v[b]);
    sum += len;
    sum2 += len * len;
  }
  s.edge_mean = sum / s.edges;
  s.edge_cv = std::sqrt(std::max(0.0, sum2 / s.edges - s.edge_mean * s.edge_mean)) / s.edge_mean;
  return s;
}

}  // namespace paver::assetgen
