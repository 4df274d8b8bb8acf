#include "pattern/surface_triangulation.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <tuple>
#include <utility>

namespace paver {
namespace {

double orient(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// > 0 when d lies inside the circle through the counter-clockwise triangle (a, b, c).
double in_circle(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, glm::dvec2 d) {
  const glm::dvec2 ad = a - d, bd = b - d, cd = c - d;
  const double a2 = glm::dot(ad, ad), b2 = glm::dot(bd, bd), c2 = glm::dot(cd, cd);
  return ad.x * (bd.y * c2 - b2 * cd.y) - ad.y * (bd.x * c2 - b2 * cd.x) + a2 * (bd.x * cd.y - bd.y * cd.x);
}

// Triangles with their neighbours: nb[t][i] lies across the edge opposite v[t][i], -1 on the hull.
struct Mesh2 {
  std::vector<glm::ivec3> v, nb;

  int edge_to(int u, int t) const {
    for (int j = 0; j < 3; ++j)
      if (nb[u][j] == t) return j;
    return -1;
  }
  void relink(int u, int from, int to) {
    if (u < 0) return;
    const int j = edge_to(u, from);
    if (j >= 0) nb[u][j] = to;
  }
};

// Whether the angles at c (in triangle c, p, q) and at d (in d, q, p) of 3D triangles add up to
// more than pi (by 1e-9): edge pq is then not Delaunay on the surface. Read from the sine of the
// sum, sin a cos b + cos a sin b < 0, without the two atan2 per edge that took a quarter of the
// valence measure on 1M elements.
bool opposite_angles_exceed_pi(const glm::dvec3& c, const glm::dvec3& p, const glm::dvec3& q, const glm::dvec3& d) {
  const glm::dvec3 a1 = p - c, b1 = q - c, a2 = q - d, b2 = p - d;
  const double sin_a = glm::length(glm::cross(a1, b1)), cos_a = glm::dot(a1, b1);  // both times |a1| |b1|
  const double sin_b = glm::length(glm::cross(a2, b2)), cos_b = glm::dot(a2, b2);  // both times |a2| |b2|
  const double scale = std::sqrt(glm::dot(a1, a1) * glm::dot(b1, b1) * glm::dot(a2, a2) * glm::dot(b2, b2));
  return sin_a * cos_b + cos_a * sin_b < -1e-9 * scale;
}

// Position of cell (x, y) along a Hilbert curve over a 2^16 x 2^16 grid: cells close on the
// curve are close in the plane.
std::uint64_t hilbert_index(std::uint32_t x, std::uint32_t y) {
  std::uint64_t d = 0;
  for (std::uint32_t s = 1u << 15; s > 0; s >>= 1) {
    const std::uint32_t rx = (x & s) ? 1 : 0, ry = (y & s) ? 1 : 0;
    d += std::uint64_t(s) * s * ((3 * rx) ^ ry);
    if (ry == 0) {  // rotate the quadrant so the curve stays continuous
      if (rx == 1) x = 0xffffu - x, y = 0xffffu - y;
      std::swap(x, y);
    }
  }
  return d;
}

// A coordinate of the unit box on the Hilbert grid.
std::uint32_t unit_cell(double v) { return std::uint32_t(std::clamp(v * 65535.0, 0.0, 65535.0)); }

// Insertion in Hilbert order (`p` lies in the unit box): each point is found by a short walk from
// the previous one, and the triangulated region grows as a compact blob, so a new point outside
// its hull sees few hull edges. (Rows walked alternately left and right, as before, put every
// point of a new row outside the hull, where its cavity could span the row: measuring 1M elements
// took 49 s, 7-12 s in this order. A biased randomized order was faster still but dropped hull
// triangles on a cocircular lattice.)
std::vector<int> insertion_order(std::span<const glm::dvec2> p) {
  const int n = int(p.size());
  std::vector<std::pair<std::uint64_t, int>> keyed(n);
  for (int i = 0; i < n; ++i) keyed[i] = {hilbert_index(unit_cell(p[i].x), unit_cell(p[i].y)), i};
  std::sort(keyed.begin(), keyed.end());
  std::vector<int> order(n);
  for (int i = 0; i < n; ++i) order[i] = keyed[i].second;
  return order;
}

}  // namespace

std::vector<glm::ivec3> triangle_neighbours(const std::vector<glm::ivec3>& triangles) {
  std::vector<glm::ivec3> nb(triangles.size(), glm::ivec3(-1));
  int vertices = 0;
  for (const glm::ivec3& t : triangles) vertices = std::max({vertices, t.x + 1, t.y + 1, t.z + 1});
  // The half-edges bucketed by the vertex they leave (a flat table, not a hash map of millions of
  // entries: measuring 1M elements spent a second here): the twin of (a, b) is the half-edge
  // (b, a) among the few that leave b. Where a directed edge repeats (not a manifold), the last
  // triangle that has it is the neighbour.
  std::vector<int> start(std::size_t(vertices) + 1, 0);
  for (const glm::ivec3& t : triangles)
    for (int i = 0; i < 3; ++i) ++start[std::size_t(t[i]) + 1];
  for (int v = 0; v < vertices; ++v) start[v + 1] += start[v];
  std::vector<int> slot(start.begin(), start.end() - 1);
  std::vector<int> half_edge(3 * triangles.size());  // 3 t + i: from t[(i + 1) % 3] to t[(i + 2) % 3]
  for (int t = 0; t < int(triangles.size()); ++t)
    for (int i = 0; i < 3; ++i) half_edge[std::size_t(slot[triangles[t][(i + 1) % 3]]++)] = 3 * t + i;
  for (int t = 0; t < int(triangles.size()); ++t)
    for (int i = 0; i < 3; ++i) {
      const int from = triangles[t][(i + 1) % 3], to = triangles[t][(i + 2) % 3];
      for (int k = start[to]; k < start[to + 1]; ++k) {
        const int h = half_edge[std::size_t(k)], u = h / 3;
        if (triangles[u][(h % 3 + 2) % 3] == from) nb[t][i] = u;
      }
    }
  return nb;
}

namespace {

// Bowyer-Watson insertion into a triangulation of the scaled points and three far corners.
class DelaunayBuilder {
public:
  // `p`: the points in the unit box, then the three corners (indices n, n + 1, n + 2).
  DelaunayBuilder(std::vector<glm::dvec2> p, int n) : p_(std::move(p)), n_(n) {
    m_.v.push_back({n, n + 1, n + 2});
    m_.nb.push_back(glm::ivec3(-1));
    alive_.push_back(1);
  }

  void insert(int i) {
    const glm::dvec2 q = p_[i];
    const int t = locate(q);
    if (t < 0) return;
    for (int k = 0; k < 3; ++k)
      if (p_[m_.v[t][k]] == q) return;  // a duplicate point
    grow_cavity(t, q);
    keep_visible_rim(t, q);
    fan_over_rim(i);
  }

  // Canonical for a given triangulation: each triangle from its lowest index, triangles along the
  // Hilbert curve through their centroids, so what is built on their order does not depend on the
  // insertion order, and loops over them walk the plane coherently. (Cocircular points, as in a
  // square lattice, can still be triangulated differently in another insertion order.)
  std::vector<glm::ivec3> triangles() const {
    std::vector<std::pair<std::uint64_t, glm::ivec3>> keyed;
    for (size_t t = 0; t < m_.v.size(); ++t)
      if (alive_[t] && m_.v[t][0] < n_ && m_.v[t][1] < n_ && m_.v[t][2] < n_) {
        glm::ivec3 t3 = m_.v[t];
        while (t3.x > t3.y || t3.x > t3.z) t3 = glm::ivec3(t3.y, t3.z, t3.x);
        const glm::dvec2 c = (p_[t3.x] + p_[t3.y] + p_[t3.z]) / 3.0;
        keyed.push_back({(hilbert_index(unit_cell(c.x), unit_cell(c.y)) << 32) | std::uint32_t(t3.x), t3});
      }
    std::sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) {
      return a.first != b.first ? a.first < b.first
                                : std::tie(a.second.y, a.second.z) < std::tie(b.second.y, b.second.z);
    });
    std::vector<glm::ivec3> out(keyed.size());
    for (size_t t = 0; t < keyed.size(); ++t) out[t] = keyed[t].second;
    return out;
  }

private:
  struct Rim {
    int a, b, outer;
  };

  bool sees(int t, int k, const glm::dvec2& q) const {
    return orient(p_[m_.v[t][(k + 1) % 3]], p_[m_.v[t][(k + 2) % 3]], q) >= 0;
  }
  bool contains(int t, const glm::dvec2& q) const { return sees(t, 0, q) && sees(t, 1, q) && sees(t, 2, q); }

  // The triangle containing q: a walk from the last one made, bounded, then a scan; -1 if none.
  int locate(const glm::dvec2& q) const {
    int t = last_;
    for (int steps = 0; t >= 0 && steps < 4 * int(m_.v.size()) + 16; ++steps) {
      int next = -1;
      for (int k = 0; k < 3 && next < 0; ++k) {
        const int e = (k + steps) % 3;
        if (!sees(t, e, q)) next = m_.nb[t][e];
      }
      if (next < 0) break;
      t = next;
    }
    if (t >= 0 && alive_[t] && contains(t, q)) return t;
    for (int u = 0; u < int(m_.v.size()); ++u)
      if (alive_[u] && contains(u, q)) return u;
    return -1;
  }

  // The cavity: triangles whose circumcircle holds q, grown from t.
  void grow_cavity(int t, const glm::dvec2& q) {
    in_cavity_.resize(m_.v.size(), 0);
    cavity_.assign(1, t);
    in_cavity_[t] = 1;
    stack_.assign(1, t);
    while (!stack_.empty()) {
      const int u = stack_.back();
      stack_.pop_back();
      for (int k = 0; k < 3; ++k) {
        const int w = m_.nb[u][k];
        if (w < 0 || in_cavity_[w]) continue;
        if (in_circle(p_[m_.v[w][0]], p_[m_.v[w][1]], p_[m_.v[w][2]], q) > 0) {
          in_cavity_[w] = 1;
          cavity_.push_back(w);
          stack_.push_back(w);
        }
      }
    }
  }

  // The cavity's rim; a triangle whose rim edge q does not see strictly (rounding) is taken back
  // out so that the new fan stays positive, and what a removal disconnects from t goes too.
  void keep_visible_rim(int t, const glm::dvec2& q) {
    for (bool changed = true; changed;) {
      changed = false;
      rim_.clear();
      for (int u : cavity_) {
        for (int k = 0; k < 3 && !changed; ++k) {
          const int w = m_.nb[u][k];
          if (w >= 0 && in_cavity_[w]) continue;
          const int a = m_.v[u][(k + 1) % 3], b = m_.v[u][(k + 2) % 3];
          if (u != t && orient(p_[a], p_[b], q) <= 0) {
            in_cavity_[u] = 0;
            cavity_.erase(std::find(cavity_.begin(), cavity_.end(), u));
            changed = true;
            break;
          }
          rim_.push_back({a, b, w});
        }
        if (changed) break;
      }
      if (changed) keep_connected(t);
    }
  }

  void keep_connected(int t) {
    for (int u : cavity_) in_cavity_[u] = 0;
    std::vector<int> kept{t};
    in_cavity_[t] = 1;
    for (size_t s = 0; s < kept.size(); ++s)
      for (int k = 0; k < 3; ++k) {
        const int w = m_.nb[kept[s]][k];
        if (w >= 0 && !in_cavity_[w] && std::find(cavity_.begin(), cavity_.end(), w) != cavity_.end())
          in_cavity_[w] = 1, kept.push_back(w);
      }
    cavity_.swap(kept);
  }

  // The fan from point i over the rim, in the cavity's freed slots first.
  void fan_over_rim(int i) {
    std::vector<int> fan(rim_.size());
    for (int u : cavity_) alive_[u] = 0, in_cavity_[u] = 0, free_slots_.push_back(u);
    for (size_t r = 0; r < rim_.size(); ++r) {
      int s;
      if (!free_slots_.empty()) {
        s = free_slots_.back();
        free_slots_.pop_back();
      } else {
        s = int(m_.v.size());
        m_.v.emplace_back();
        m_.nb.emplace_back();
        alive_.push_back(0);
        in_cavity_.push_back(0);
      }
      fan[r] = s;
      m_.v[s] = {i, rim_[r].a, rim_[r].b};
      m_.nb[s] = {rim_[r].outer, -1, -1};
      alive_[s] = 1;
    }
    for (size_t r = 0; r < rim_.size(); ++r) {
      const int s = fan[r];
      if (const int o = rim_[r].outer; o >= 0)
        for (int k = 0; k < 3; ++k)
          if (m_.v[o][(k + 1) % 3] == rim_[r].b && m_.v[o][(k + 2) % 3] == rim_[r].a) m_.nb[o][k] = s;
      // Across (a_r, q), opposite b_r: the fan triangle whose rim edge ends at a_r; across
      // (q, b_r), opposite a_r: the one whose rim edge starts at b_r.
      for (size_t o = 0; o < rim_.size(); ++o) {
        if (rim_[o].b == rim_[r].a) m_.nb[s][2] = fan[o];
        if (rim_[o].a == rim_[r].b) m_.nb[s][1] = fan[o];
      }
    }
    last_ = fan.empty() ? last_ : fan[0];
  }

  std::vector<glm::dvec2> p_;
  int n_;
  Mesh2 m_;
  std::vector<char> alive_, in_cavity_;
  std::vector<int> free_slots_, cavity_, stack_;
  std::vector<Rim> rim_;
  int last_ = 0;
};

}  // namespace

std::vector<glm::ivec3> delaunay_triangulation(std::span<const glm::dvec2> points) {
  const int n = int(points.size());
  if (n < 3) return {};
  glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (const glm::dvec2& p : points) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const double size = std::max({hi.x - lo.x, hi.y - lo.y, 1e-300});
  // Points in a local frame scaled to the unit box, then three far corners around them.
  std::vector<glm::dvec2> p(n + 3);
  for (int i = 0; i < n; ++i) p[i] = (points[i] - lo) / size;
  // Far enough that only a hull point within about 1e-5 of the hull's line (a circumcircle wider
  // than the corners) can miss its hull triangle; near enough for in_circle to stay exact there.
  constexpr double kFar = 1e5;
  p[n] = {-kFar, -kFar}, p[n + 1] = {kFar, -kFar}, p[n + 2] = {0.5, kFar};
  const std::vector<int> order = insertion_order(std::span(p.data(), n));
  DelaunayBuilder builder(std::move(p), n);
  for (int i : order) builder.insert(i);
  return builder.triangles();
}

int flip_to_surface_delaunay(std::vector<glm::ivec3>& triangles, std::span<const glm::dvec2> uv,
                             std::span<const glm::dvec3> position) {
  Mesh2 m{triangles, triangle_neighbours(triangles)};
  const int nt = int(triangles.size());
  std::vector<std::pair<int, int>> queue;
  for (int t = 0; t < nt; ++t)
    for (int i = 0; i < 3; ++i) queue.emplace_back(t, i);
  int flips = 0;
  // Extrinsic angles need not settle like intrinsic ones: a bound keeps a rare cycle finite.
  const long max_flips = 10L * nt + 100;
  while (!queue.empty() && flips < max_flips) {
    const auto [t, i] = queue.back();
    queue.pop_back();
    const int u = m.nb[t][i];
    if (u < 0) continue;
    const int j = m.edge_to(u, t);
    if (j < 0) continue;
    const int c = m.v[t][i], p = m.v[t][(i + 1) % 3], q = m.v[t][(i + 2) % 3], d = m.v[u][j];
    if (m.v[u][(j + 1) % 3] != q || m.v[u][(j + 2) % 3] != p || c == d) continue;
    if (!opposite_angles_exceed_pi(position[c], position[p], position[q], position[d])) continue;
    // The flipped pair must stay positive in the map, or the triangulation would fold.
    const double scale = glm::dot(uv[p] - uv[q], uv[p] - uv[q]);
    if (orient(uv[c], uv[p], uv[d]) <= 1e-12 * scale || orient(uv[d], uv[q], uv[c]) <= 1e-12 * scale) continue;
    const int e_qc = m.nb[t][(i + 1) % 3], e_cp = m.nb[t][(i + 2) % 3];
    const int e_pd = m.nb[u][(j + 1) % 3], e_dq = m.nb[u][(j + 2) % 3];
    m.v[t] = {c, p, d};
    m.nb[t] = {e_pd, u, e_cp};
    m.v[u] = {d, q, c};
    m.nb[u] = {e_qc, t, e_dq};
    m.relink(e_pd, u, t);
    m.relink(e_qc, t, u);
    ++flips;
    queue.emplace_back(t, 0), queue.emplace_back(t, 2), queue.emplace_back(u, 0), queue.emplace_back(u, 2);
  }
  triangles = m.v;
  return flips;
}

std::vector<glm::ivec3> triangulate_surface_points(std::span<const glm::dvec2> uv,
                                                   std::span<const glm::dvec3> position, double longest_edge) {
  std::vector<glm::ivec3> triangles = delaunay_triangulation(uv);
  flip_to_surface_delaunay(triangles, uv, position);
  std::erase_if(triangles, [&](const glm::ivec3& t) {
    for (int k = 0; k < 3; ++k)
      if (glm::length(position[t[k]] - position[t[(k + 1) % 3]]) > longest_edge) return true;
    return false;
  });
  return triangles;
}

}  // namespace paver
