#include "map/seamless_band.h"

#include "map/map_quality.h"
#include "mesh/triangle_geometry.h"

#include <Eigen/Sparse>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <unordered_map>

namespace paver {
namespace {

constexpr int kMaxIterations = 100;
constexpr double kTolerance = 1e-6;  // relative energy decrease that ends the iterations
constexpr int kMaxHalvings = 30;

// The current periodic map: one uv per vertex and the period vector.
struct PeriodicUv {
  std::vector<glm::dvec2> uv;
  glm::dvec2 t{0};
};

glm::dvec2 corner(const PeriodicUv& m, int v, int turns) { return m.uv[v] + double(turns) * m.t; }

double signed_area_of(const PeriodicUv& m, const glm::ivec3& tri, const glm::ivec3& turns) {
  return detail::signed_area(corner(m, tri.x, turns.x), corner(m, tri.y, turns.y), corner(m, tri.z, turns.z));
}

bool folds(const SurfaceMesh& mesh, const std::vector<glm::ivec3>& turns, const PeriodicUv& m) {
  for (int f = 0; f < mesh.face_count(); ++f)
    if (!(signed_area_of(m, mesh.triangles[f], turns[f]) > 0)) return true;
  return false;
}

class PeriodicArap {
public:
  PeriodicArap(const SurfaceMesh& mesh, std::vector<glm::ivec3> turns) : mesh_(mesh), turns_(std::move(turns)) {
    const int nf = mesh.face_count(), nv = mesh.vertex_count();
    flat_.resize(nf);
    cot_.resize(nf);
    for (int f = 0; f < nf; ++f) {
      const glm::ivec3 t = mesh.triangles[f];
      const glm::dvec3 p[3] = {mesh.positions[t.x], mesh.positions[t.y], mesh.positions[t.z]};
      flat_[f] = detail::flatten_triangle(p[0], p[1], p[2]);
      for (int k = 0; k < 3; ++k) cot_[f][k] = detail::cotangent(p[k], p[(k + 1) % 3], p[(k + 2) % 3]);
    }
    // Unknowns: every vertex but the pinned one (vertex 0), then T.
    unknowns_ = nv;  // nv - 1 vertices + T
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(std::size_t(nf) * 27);
    for_each_term([&](int, int, const Term& term) {
      for (int a = 0; a < term.count; ++a)
        for (int b = 0; b < term.count; ++b)
          entries.emplace_back(term.index[a], term.index[b], term.w * term.coef[a] * term.coef[b]);
    });
    Eigen::SparseMatrix<double> system(unknowns_, unknowns_);
    system.setFromTriplets(entries.begin(), entries.end());
    solver_.compute(system);
    ok_ = solver_.info() == Eigen::Success;
  }

  bool factorized() const { return ok_; }

  double energy(const PeriodicUv& m) const {
    double e = 0;
    for (int f = 0; f < mesh_.face_count(); ++f) {
      const double angle = best_rotation(m, f);
      for (int k = 0; k < 3; ++k) {
        const glm::dvec2 d = edge_now(m, f, k) - rotate(edge_rest(f, k), angle);
        e += cot_[f][k] * glm::dot(d, d);
      }
    }
    return e;
  }

  // One local/global step: the map that the rotations fitted to `m` ask for.
  PeriodicUv global_step(const PeriodicUv& m) const {
    std::vector<double> rotation(mesh_.face_count());
    for (int f = 0; f < mesh_.face_count(); ++f) rotation[f] = best_rotation(m, f);
    Eigen::VectorXd bx = Eigen::VectorXd::Zero(unknowns_), by = Eigen::VectorXd::Zero(unknowns_);
    const glm::dvec2 pinned = m.uv[0];
    for_each_term([&](int f, int k, const Term& term) {
      glm::dvec2 target = rotate(edge_rest(f, k), rotation[f]) - term.pinned_coef * pinned;
      for (int a = 0; a < term.count; ++a) {
        bx[term.index[a]] += term.w * term.coef[a] * target.x;
        by[term.index[a]] += term.w * term.coef[a] * target.y;
      }
    });
    const Eigen::VectorXd x = solver_.solve(bx), y = solver_.solve(by);
    PeriodicUv next;
    next.uv.resize(mesh_.vertex_count());
    next.uv[0] = pinned;
    for (int v = 1; v < mesh_.vertex_count(); ++v) next.uv[v] = {x[v - 1], y[v - 1]};
    next.t = {x[unknowns_ - 1], y[unknowns_ - 1]};
    return next;
  }

private:
  // One edge term of the energy, w |sum coef[a] z[index[a]] + pinned_coef * uv_pinned - R e|^2.
  struct Term {
    double w = 0;
    int count = 0;
    int index[3];
    double coef[3];
    double pinned_coef = 0;
  };

  template <class F>
  void for_each_term(F&& f) const {
    for (int face = 0; face < mesh_.face_count(); ++face) {
      const glm::ivec3 tri = mesh_.triangles[face], turns = turns_[face];
      for (int k = 0; k < 3; ++k) {
        const int i = tri[(k + 1) % 3], j = tri[(k + 2) % 3];
        const double shift = double(turns[(k + 2) % 3] - turns[(k + 1) % 3]);
        Term term;
        term.w = cot_[face][k];
        const auto add = [&](int index, double c) {
          if (c == 0) return;
          term.index[term.count] = index;
          term.coef[term.count++] = c;
        };
        if (j == 0) term.pinned_coef += 1; else add(j - 1, 1);
        if (i == 0) term.pinned_coef -= 1; else add(i - 1, -1);
        add(unknowns_ - 1, shift);
        f(face, k, term);
      }
    }
  }

  glm::dvec2 edge_now(const PeriodicUv& m, int f, int k) const {
    const glm::ivec3 tri = mesh_.triangles[f], turns = turns_[f];
    const int a = (k + 1) % 3, b = (k + 2) % 3;
    return corner(m, tri[b], turns[b]) - corner(m, tri[a], turns[a]);
  }
  glm::dvec2 edge_rest(int f, int k) const { return flat_[f][(k + 2) % 3] - flat_[f][(k + 1) % 3]; }
  static glm::dvec2 rotate(glm::dvec2 v, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    return {c * v.x - s * v.y, s * v.x + c * v.y};
  }
  // The rotation R maximising sum w (d . R e) over the triangle's edges.
  double best_rotation(const PeriodicUv& m, int f) const {
    double along = 0, across = 0;
    for (int k = 0; k < 3; ++k) {
      const glm::dvec2 d = edge_now(m, f, k), e = edge_rest(f, k);
      along += cot_[f][k] * (d.x * e.x + d.y * e.y);
      across += cot_[f][k] * (d.y * e.x - d.x * e.y);
    }
    return std::atan2(across, along);
  }

  const SurfaceMesh& mesh_;
  std::vector<glm::ivec3> turns_;
  std::vector<std::array<glm::dvec2, 3>> flat_;
  std::vector<std::array<double, 3>> cot_;
  int unknowns_ = 0;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver_;
  bool ok_ = false;
};

PeriodicUv blend(const PeriodicUv& a, const PeriodicUv& b, double s) {
  PeriodicUv r;
  r.uv.resize(a.uv.size());
  for (std::size_t v = 0; v < a.uv.size(); ++v) r.uv[v] = a.uv[v] + s * (b.uv[v] - a.uv[v]);
  r.t = a.t + s * (b.t - a.t);
  return r;
}

// The domain vertex of (v, turns): one per distinct pair.
struct DomainBuilder {
  MapDomain domain;
  std::unordered_map<long long, int> index;
  int add(int v, int turns, glm::dvec2 uv) {
    const long long key = (long long)v * 64 + (turns + 32);
    const auto [it, added] = index.try_emplace(key, int(domain.uv.size()));
    if (added) {
      domain.uv.push_back(uv);
      domain.vertex.push_back(v);
    }
    return it->second;
  }
};

// Why the rims of `m` are not those of a bijective band map, or empty: each rim, unrolled along
// itself, must close one period T away from where it started (go once around), and over three
// periods neither may cross itself or the other. ARAP's fold-free steps keep every triangle
// positive but not the rims apart: the line search checks this too.
std::string rim_problem(const SurfaceMesh& band, const PeriodicUv& m) {
  const double tt = glm::dot(m.t, m.t);
  if (!(tt > 0)) return "the band's period collapsed";
  const auto image_near = [&](glm::dvec2 q, glm::dvec2 near) {
    return q - m.t * std::floor(glm::dot(q - near, m.t) / tt + 0.5);
  };
  std::vector<glm::dvec2> rim_uv;
  std::vector<glm::ivec2> rim_segments;
  for (const std::vector<int>& loop : band.boundary_loops) {
    std::vector<glm::dvec2> unrolled;
    for (const int v : loop) unrolled.push_back(unrolled.empty() ? m.uv[v] : image_near(m.uv[v], unrolled.back()));
    const glm::dvec2 closing = image_near(unrolled.front(), unrolled.back()) - unrolled.front();
    if (glm::length(glm::abs(closing) - glm::abs(m.t)) > 1e-6 * std::sqrt(tt))
      return "a rim of the band does not go once around its seamless map";
    const int first = int(rim_uv.size());
    for (int copy = -1; copy <= 1; ++copy)
      for (const glm::dvec2& q : unrolled) rim_uv.push_back(q + double(copy) * closing);
    for (int k = first; k + 1 < int(rim_uv.size()); ++k) rim_segments.emplace_back(k, k + 1);
  }
  if (count_segment_intersections(rim_segments, rim_uv) > 0) return "the band's rims cross on its seamless map";
  return "";
}

}  // namespace

std::optional<SeamlessBandMap> map_band_seamlessly(const SurfaceMesh& band, const std::vector<glm::dvec2>& annulus_uv,
                                                  glm::dvec2 hole_centre, std::string& why_not) {
  const int nv = band.vertex_count(), nf = band.face_count();
  if (band.boundary_loops.size() != 2 || nv < 3) {
    why_not = "the surface is not a band (two boundary loops)";
    return std::nullopt;
  }
  // Log-polar start: angle along the band, log radius across, scaled by the mean radius.
  double radius = 0;
  for (const glm::dvec2& q : annulus_uv) radius += glm::length(q - hole_centre);
  radius /= double(nv);
  constexpr double kTurn = 2 * std::numbers::pi;
  std::vector<double> angle(nv);
  PeriodicUv start;
  start.uv.resize(nv);
  for (int v = 0; v < nv; ++v) {
    const glm::dvec2 d = annulus_uv[v] - hole_centre;
    const double r = glm::length(d);
    if (!(r > 0)) {
      why_not = "the hole's centre lies on the surface's map";
      return std::nullopt;
    }
    angle[v] = std::atan2(d.y, d.x);
    start.uv[v] = glm::dvec2(radius * angle[v], -radius * std::log(r / radius));
  }
  start.t = glm::dvec2(radius * kTurn, 0);
  std::vector<glm::ivec3> turns(nf);
  for (int f = 0; f < nf; ++f) {
    const glm::ivec3 t = band.triangles[f];
    for (int k = 0; k < 3; ++k) turns[f][k] = int(std::lround((angle[t.x] - angle[t[k]]) / kTurn));
  }
  if (folds(band, turns, start)) {
    why_not = "its annulus map does not unroll without folds";
    return std::nullopt;
  }
  if (const std::string problem = rim_problem(band, start); !problem.empty()) {
    why_not = problem + " (as unrolled from its annulus map)";
    return std::nullopt;
  }

  PeriodicArap arap(band, turns);
  if (!arap.factorized()) {
    why_not = "the band's ARAP system cannot be factorized";
    return std::nullopt;
  }
  PeriodicUv current = std::move(start);
  double energy = arap.energy(current);
  SeamlessBandMap out;
  for (int it = 0; it < kMaxIterations; ++it) {
    const PeriodicUv target = arap.global_step(current);
    // Shortened until nothing folds and the energy does not grow.
    double step = 1;
    PeriodicUv trial = target;
    double trial_energy = 0;
    int halvings = 0;
    for (; halvings < kMaxHalvings; ++halvings, step *= 0.5) {
      trial = blend(current, target, step);
      if (folds(band, turns, trial) || !rim_problem(band, trial).empty()) continue;
      trial_energy = arap.energy(trial);
      if (trial_energy <= energy) break;
    }
    if (halvings == kMaxHalvings) break;
    ++out.iterations;
    const double decrease = energy - trial_energy;
    current = std::move(trial);
    energy = trial_energy;
    if (decrease <= kTolerance * energy) break;
  }

  // T along +u, area equal to the surface's.
  const double length = glm::length(current.t);
  if (!(length > 0)) {
    why_not = "the band's period collapsed";
    return std::nullopt;
  }
  const glm::dvec2 along = current.t / length;
  double area = 0;
  for (int f = 0; f < nf; ++f) area += signed_area_of(current, band.triangles[f], turns[f]);
  const double scale = std::sqrt(surface_area(band) / area);
  out.uv.resize(nv);
  for (int v = 0; v < nv; ++v) {
    const glm::dvec2 q = current.uv[v] - current.uv[0];
    out.uv[v] = scale * glm::dvec2(along.x * q.x + along.y * q.y, -along.y * q.x + along.x * q.y);
  }
  out.period = scale * length;
  out.corner_turns = std::move(turns);

  return out;
}

SurfaceMap make_seamless_surface_map(const SurfaceMap& annulus, const SeamlessBandMap& band) {
  SurfaceMap map;
  map.mesh = annulus.mesh;
  map.uv = band.uv;
  map.normals = annulus.normals;
  map.curvature = annulus.curvature;
  map.curvature_min = annulus.curvature_min, map.curvature_max = annulus.curvature_max;
  map.parameterization = annulus.parameterization;
  map.parameterization.uv = band.uv;
  map.parameterization.hole_centres.clear();
  map.period = band.period;

  DomainBuilder builder;
  const int nf = map.mesh.face_count();
  std::vector<glm::ivec3> first(nf);
  for (int f = 0; f < nf; ++f) {
    const glm::ivec3 t = map.mesh.triangles[f], turns = band.corner_turns[f];
    for (int k = 0; k < 3; ++k) first[f][k] = builder.add(t[k], turns[k], band.uv[t[k]] + glm::dvec2(turns[k] * band.period, 0));
  }
  MapDomain& domain = builder.domain;
  const int one_copy = int(domain.uv.size());
  for (const double shift : {-band.period, band.period})
    for (int d = 0; d < one_copy; ++d) {
      domain.uv.push_back(domain.uv[d] + glm::dvec2(shift, 0));
      domain.vertex.push_back(domain.vertex[d]);
    }
  domain.triangles = first;
  for (const int copy : {1, 2})
    for (const glm::ivec3& t : first) domain.triangles.push_back(t + glm::ivec3(copy * one_copy));

  // One period, from the domain's own left edge: the first copy and the one before it cover it.
  glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (int d = 0; d < one_copy; ++d) lo = glm::min(lo, domain.uv[d]), hi = glm::max(hi, domain.uv[d]);
  map.period_origin = lo.x;
  map.uv_min = lo;
  map.uv_max = glm::dvec2(lo.x + band.period, hi.y);
  // Its quality as measure_map sees one period: the first copy's triangles, each in one piece.
  SurfaceMesh one_period;
  for (const int v : domain.vertex) one_period.positions.push_back(map.mesh.positions[v]);
  one_period.triangles = first;
  map.parameterization.quality = measure_map(one_period, domain.uv);
  map.domain = std::move(domain);
  map.grid = build_uv_grid(map.domain.uv, map.domain.triangles);
  return map;
}

void add_seamless_map(SurfaceMap& annulus) {
  if (!is_band(annulus)) return;
  annulus.seamless_unavailable = not_a_band(annulus);
  if (!annulus.seamless_unavailable.empty()) return;
  if (annulus.parameterization.hole_centres.size() != 1) {
    annulus.seamless_unavailable = "its map has no hole centre";
    return;
  }
  std::string why_not;
  const std::optional<SeamlessBandMap> band =
      map_band_seamlessly(annulus.mesh, annulus.uv, annulus.parameterization.hole_centres.front(), why_not);
  if (!band) {
    annulus.seamless_unavailable = why_not;
    return;
  }
  annulus.seamless = std::make_shared<const SurfaceMap>(make_seamless_surface_map(annulus, *band));
}

std::string not_a_band(const SurfaceMap& annulus) {
  if (annulus.parameterization.report.planar)
    return "it is flat: its plane holds a regular lattice everywhere, where rows closed around the hole would fan out";
  // The outer loop is the longer (SurfaceMesh::boundary_loops).
  const double longer = loop_length(annulus.mesh.positions, annulus.mesh.outer_loop()),
               shorter = loop_length(annulus.mesh.positions, annulus.mesh.boundary_loops[1]);
  if (shorter < kBandRimRatio * longer) {
    char why[200];
    std::snprintf(why, sizeof why,
                  "its inner rim (%.4g long) is under %g of the outer (%.4g): a hole in the surface, which rows closed "
                  "around it would cross %.1f times closer at the hole than at the edge",
                  shorter, kBandRimRatio, longer, longer / shorter);
    return why;
  }
  return "";
}

}  // namespace paver
