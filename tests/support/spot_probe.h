#pragma once
// Bare spots and rim metal found the plainest way, apart from the engine's search
// (elements/bare_spots.h, report/edge_quality.h): every mesh triangle sampled on a fine barycentric
// grid, each sample's room measured against every element in its bucket and every boundary
// segment in its bucket, buckets of the test's own.
#include "elements/elements.h"
#include "mesh/surface_mesh.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <vector>

namespace paver::test {

class Buckets {
public:
  explicit Buckets(double cell) : cell_(cell) {}
  void add(const glm::dvec3& lo, const glm::dvec3& hi, int item) {
    for (long x = index(lo.x); x <= index(hi.x); ++x)
      for (long y = index(lo.y); y <= index(hi.y); ++y)
        for (long z = index(lo.z); z <= index(hi.z); ++z) cells_[key(x, y, z)].push_back(item);
  }
  template <class Visit>
  void near(const glm::dvec3& p, Visit&& visit) const {
    for (long x = index(p.x) - 1; x <= index(p.x) + 1; ++x)
      for (long y = index(p.y) - 1; y <= index(p.y) + 1; ++y)
        for (long z = index(p.z) - 1; z <= index(p.z) + 1; ++z)
          if (const auto it = cells_.find(key(x, y, z)); it != cells_.end())
            for (int item : it->second) visit(item);
  }

private:
  long index(double v) const { return long(std::floor(v / cell_)); }
  static std::int64_t key(long x, long y, long z) { return (x * 73856093L) ^ (y * 19349663L) ^ (z * 83492791L); }
  double cell_;
  std::unordered_map<std::int64_t, std::vector<int>> cells_;
};

struct SpotProbe {
  double widest = 0;                    // the widest stone that fits anywhere sampled (capped at `cap`)
  std::vector<glm::dvec3> fitting;      // samples where a stone of `wanted` fits
};

// The room at every sample: 2 min(distance to an element's centre - its radius - gap, distance to
// the boundary - margin), capped at `cap`; `rims` false: no boundary (a closed surface's seams).
inline SpotProbe probe_spots(const SurfaceMesh& mesh, const Elements& e, double gap, double margin, double wanted,
                             double step, double cap, bool rims = true) {
  double largest = 0;
  for (double d : e.diameter) largest = std::max(largest, d);
  const double reach = 0.5 * cap + 0.5 * largest + gap + margin;
  Buckets stones(reach), segments(reach);
  for (int i = 0; i < int(e.size()); ++i) stones.add(e.position[i], e.position[i], i);
  std::vector<std::pair<glm::dvec3, glm::dvec3>> boundary;
  if (rims)
    for (const std::vector<int>& loop : mesh.boundary_loops)
      for (std::size_t k = 0; k < loop.size(); ++k) {
        const glm::dvec3 a = mesh.positions[loop[k]], b = mesh.positions[loop[(k + 1) % loop.size()]];
        segments.add(glm::min(a, b), glm::max(a, b), int(boundary.size()));
        boundary.emplace_back(a, b);
      }
  SpotProbe probe;
  for (const glm::ivec3& t : mesh.triangles) {
    const glm::dvec3 a = mesh.positions[t.x], b = mesh.positions[t.y], c = mesh.positions[t.z];
    const double longest = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
    const int n = std::max(1, int(std::ceil(longest / step)));
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) {
        const glm::dvec3 p = a + (double(i) / n) * (b - a) + (double(j) / n) * (c - a);
        double room = 0.5 * cap;
        stones.near(p, [&](int k) { room = std::min(room, glm::length(p - e.position[k]) - 0.5 * e.diameter[k] - gap); });
        segments.near(p, [&](int s) {
          const auto& [u, v] = boundary[std::size_t(s)];
          const glm::dvec3 uv = v - u;
          const double along = std::clamp(glm::dot(p - u, uv) / std::max(glm::dot(uv, uv), 1e-300), 0.0, 1.0);
          room = std::min(room, glm::length(p - (u + along * uv)) - margin);
        });
        probe.widest = std::max(probe.widest, 2 * room);
        if (2 * room >= wanted) probe.fitting.push_back(p);
      }
  }
  return probe;
}

// Along the loops `rims`, every `step`: the distance to the nearest element's girdle less the
// margin, over every element (no buckets: rims are short).
inline std::vector<double> probe_rim_metal(const SurfaceMesh& mesh, const Elements& e, const std::vector<int>& rims,
                                           double margin, double step) {
  std::vector<double> metal;
  for (const int l : rims) {
    const std::vector<int>& loop = mesh.boundary_loops[std::size_t(l)];
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const glm::dvec3 a = mesh.positions[loop[k]], b = mesh.positions[loop[(k + 1) % loop.size()]];
      const int n = std::max(1, int(std::ceil(glm::length(b - a) / step)));
      for (int i = 0; i < n; ++i) {
        const glm::dvec3 q = a + (double(i) / n) * (b - a);
        double nearest = std::numeric_limits<double>::infinity();
        for (std::size_t s = 0; s < e.size(); ++s)
          nearest = std::min(nearest, glm::length(q - e.position[s]) - 0.5 * e.diameter[s]);
        metal.push_back(nearest - margin);
      }
    }
  }
  return metal;
}

// Stones of `stone` on a triangle lattice `stone + gap` apart over the unit square [0, 1]^2 at
// z = 0, those within `margin` of its edge (the footprint's) left out, and the one nearest the
// middle taken out: its place is `hole`.
inline Elements square_lattice(double stone, double gap, double margin, glm::dvec3& hole) {
  const double D = stone + gap;
  std::vector<glm::dvec2> uv;
  for (int j = -2; j * D * std::sqrt(3.0) / 2 < 1.2; ++j)
    for (int i = -2; i * D < 1.2; ++i) {
      const glm::dvec2 p((i + 0.5 * (j & 1)) * D + 0.013, j * D * std::sqrt(3.0) / 2 + 0.021);
      if (std::min({p.x, p.y, 1 - p.x, 1 - p.y}) >= 0.5 * stone + margin) uv.push_back(p);
    }
  std::size_t middle = 0;
  for (std::size_t k = 0; k < uv.size(); ++k)
    if (glm::length(uv[k] - glm::dvec2(0.5)) < glm::length(uv[middle] - glm::dvec2(0.5))) middle = k;
  hole = glm::dvec3(uv[middle], 0);
  uv.erase(uv.begin() + std::ptrdiff_t(middle));
  Elements e;
  for (const glm::dvec2& p : uv)
    e.push_back(ElementKind::Vertex, 0, 0, p, glm::dvec3(p, 0), glm::dvec3(0, 0, 1), stone, ShapeKind::Gem);
  return e;
}

}  // namespace paver::test
