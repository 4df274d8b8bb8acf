#include "mesh_building.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <cstddef>
#include <utility>

namespace paver::assetgen {

using glm::dvec3;

Row make_row(Mesh& m, int segments, const std::function<dvec3(double)>& at) {
  Row r;
  for (int j = 0; j <= segments; ++j) {
    const double t = static_cast<double>(j) / segments;
    r.idx.push_back(m.add(at(t)));
    r.t.push_back(t);
  }
  return r;
}

Row make_ring(Mesh& m, int n, const std::function<dvec3(double)>& at) {
  Row r;
  for (int j = 0; j < n; ++j) {
    const double t = static_cast<double>(j) / n;
    r.idx.push_back(m.add(at(t)));
    r.t.push_back(t);
  }
  return r;
}

void stitch(Mesh& m, const Row& a, const Row& b, bool closed) {
  const std::size_t na = a.idx.size();
  const std::size_t nb = b.idx.size();
  const std::size_t steps_a = closed ? na : na - 1;
  const std::size_t steps_b = closed ? nb : nb - 1;
  const auto vid = [](const Row& r, std::size_t i) { return r.idx[i % r.idx.size()]; };
  const auto param = [](const Row& r, std::size_t i) {
    return i < r.t.size() ? r.t[i] : 1.0 + r.t[i - r.t.size()];
  };
  std::size_t i = 0;
  std::size_t j = 0;
  while (i < steps_a || j < steps_b) {
    bool advance_a = false;
    if (i == steps_a) {
      advance_a = false;
    } else if (j == steps_b) {
      advance_a = true;
    } else {
      const double da = glm::distance(m.v[vid(a, i + 1)], m.v[vid(b, j)]);
      const double db = glm::distance(m.v[vid(a, i)], m.v[vid(b, j + 1)]);
      // Equal diagonals happen on symmetric layouts; the parameter keeps the choice stable.
      advance_a = std::abs(da - db) > 1e-9 * (da + db) ? da < db
                                                         : param(a, i + 1) <= param(b, j + 1);
    }
    if (advance_a) {
      m.f.push_back({vid(a, i), vid(b, j), vid(a, i + 1)});
      ++i;
    } else {
      m.f.push_back({vid(a, i), vid(b, j), vid(b, j + 1)});
      ++j;
    }
  }
}

void stitch_rings(Mesh& m, int centre, const std::vector<Row>& rings) {
  const Row& first = rings.front();
  for (std::size_t j = 0; j < first.idx.size(); ++j)
    m.f.push_back({centre, first.idx[j], first.idx[(j + 1) % first.idx.size()]});
  for (std::size_t k = 1; k < rings.size(); ++k) stitch(m, rings[k - 1], rings[k], true);
}

dvec3 face_normal(const Mesh& m, const std::array<int, 3>& t) {
  return glm::cross(m.v[t[1]] - m.v[t[0]], m.v[t[2]] - m.v[t[0]]);
}

dvec3 centroid(const Mesh& m, const std::array<int, 3>& t) {
  return (m.v[t[0]] + m.v[t[1]] + m.v[t[2]]) / 3.0;
}

void orient(Mesh& m, const Outward& outward) {
  double score = 0.0;
  for (const auto& t : m.f)
    score += glm::dot(face_normal(m, t), outward(centroid(m, t))) > 0.0 ? 1.0 : -1.0;
  if (score < 0.0)
    for (auto& t : m.f) std::swap(t[1], t[2]);
}

Mesh drop_unused_vertices(const Mesh& m) {
  std::vector<int> index(m.v.size(), -1);
  Mesh out;
  for (const auto& t : m.f)
    for (int v : t)
      if (index[v] < 0) index[v] = -2;
  for (std::size_t v = 0; v < m.v.size(); ++v)
    if (index[v] == -2) index[v] = out.add(m.v[v]);
  out.f.reserve(m.f.size());
  for (const auto& t : m.f) out.f.push_back({index[t[0]], index[t[1]], index[t[2]]});
  return out;
}

Mesh fit_faces(const std::function<Mesh(double)>& build, double h, int target) {
  Mesh m = build(h);
  for (int round = 0; round < 4; ++round) {
    h *= std::sqrt(static_cast<double>(m.f.size()) / target);
    m = build(h);
  }
  return m;
}

}  // namespace paver::assetgen
