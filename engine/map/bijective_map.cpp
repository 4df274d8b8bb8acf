#include "map/bijective_map.h"

#include <cstdio>

#include <glm/matrix.hpp>

#include "core/input_error.h"
#include "core/stopwatch.h"
#include "map/hole_patches.h"
#include "map/lscm.h"
#include "map/planar_map.h"
#include "map/tutte_embedding.h"
#include "mesh/surface_scaling.h"
#include "mesh/triangle_geometry.h"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace paver {
namespace {


// Smallest alpha > 0 where det([e1 + alpha f1, e2 + alpha f2]) reaches zero, or +inf.
double first_collapse(glm::dvec2 e1, glm::dvec2 e2, glm::dvec2 f1, glm::dvec2 f2) {
  const double c = detail::cross2(e1, e2);
  const double b = detail::cross2(e1, f2) + detail::cross2(f1, e2);
  const double a = detail::cross2(f1, f2);
  constexpr double inf = std::numeric_limits<double>::infinity();
  const double scale = std::abs(a) + std::abs(b) + std::abs(c);
  if (std::abs(a) <= 1e-14 * scale) return b < 0 ? -c / b : inf;
  const double disc = b * b - 4 * a * c;
  if (disc < 0) return inf;
  // Numerically stable roots of a x^2 + b x + c.
  const double qv = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  double best = inf;
  for (double root : {qv / a, qv != 0 ? c / qv : inf})
    if (root > 0 && root < best) best = root;
  return best;
}

// A patch triangle's rest shape: its hole edge as base, its two other sides the larger of the
// hole's mean radius and 0.6 of the base (an isosceles triangle that is never a sliver, whatever
// the hole's shape).
std::array<glm::dvec2, 3> patch_rest_shape(const SurfaceMesh& mesh, const glm::ivec3& t, double radius) {
  const double base = glm::length(mesh.positions[t.y] - mesh.positions[t.x]);
  const double side = std::max(radius, 0.6 * base);
  const double height = std::sqrt(std::max(side * side - 0.25 * base * base, 1e-12 * base * base));
  return {glm::dvec2(0, 0), glm::dvec2(base, 0), glm::dvec2(0.5 * base, height)};
}

double cotangent_2d(glm::dvec2 apex, glm::dvec2 q, glm::dvec2 r) {
  const glm::dvec2 u = q - apex, v = r - apex;
  return glm::dot(u, v) / std::max(std::abs(detail::cross2(u, v)), 1e-300);
}

}  // namespace

struct MapSolver::Impl {
  PatchedSurface patched;  // holes closed; the map of the real vertices is its first part
  const SurfaceMesh& mesh = patched.mesh;
  MapOptions options;
  MapReport report;
  std::vector<std::array<glm::dvec2, 3>> flat;  // #F isometric 2D frames
  std::vector<std::array<double, 3>> cot;        // #F cot of the angle at each corner
  std::vector<double> rotation;                  // #F rotation angle of the local step
  std::vector<int> reduced;                      // #V index in the system, -1 for the pinned vertex
  Eigen::SparseMatrix<double> pinned_column;     // L restricted to (free rows, pinned column)
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> cholesky;
  std::vector<glm::dvec2> uv, target, trial;
  double trial_energy = 0;
  double energy = std::numeric_limits<double>::infinity();
  int pinned_vertex = 0;

  std::vector<double> face_weight;  // #F 1, or kHolePatchWeight on a patch
  std::vector<double> area3;        // #F 3D triangle areas (a patch's: of its rest shape)

  Impl(const SurfaceMesh& m, const MapOptions& o) : patched(close_holes(m)), options(o) { report.energy = o.energy; }

  void precompute() {
    const Stopwatch watch;
    const int n = mesh.vertex_count(), nf = mesh.face_count();
    flat.resize(nf);
    cot.resize(nf);
    rotation.assign(nf, 0);
    area3.resize(nf);
    face_weight.assign(nf, 1.0);
    for (int f = 0; f < nf; ++f) {
      const auto& t = mesh.triangles[f];
      if (patched.is_patch(f)) {
        flat[f] = patch_rest_shape(mesh, t, patched.hole_radius(f));
        for (int k = 0; k < 3; ++k)
          cot[f][k] = kHolePatchWeight * cotangent_2d(flat[f][k], flat[f][(k + 1) % 3], flat[f][(k + 2) % 3]);
        area3[f] = 0.5 * flat[f][1].x * flat[f][2].y;
        face_weight[f] = kHolePatchWeight;
        continue;
      }
      const glm::dvec3 p[3] = {mesh.positions[t.x], mesh.positions[t.y], mesh.positions[t.z]};
      flat[f] = detail::flatten_triangle(p[0], p[1], p[2]);
      for (int k = 0; k < 3; ++k) cot[f][k] = detail::cotangent(p[k], p[(k + 1) % 3], p[(k + 2) % 3]);
      area3[f] = detail::triangle_area(p[0], p[1], p[2]);
    }

    // Global step: L u = b with L the cotangent Laplacian (per-triangle weights are
    // positive semi-definite even for obtuse triangles), one vertex pinned for translation.
    pinned_vertex = mesh.boundary_loops.empty() ? 0 : mesh.outer_loop().front();
    reduced.assign(n, -1);
    int free_count = 0;
    for (int v = 0; v < n; ++v)
      if (v != pinned_vertex) reduced[v] = free_count++;
    std::vector<Eigen::Triplet<double>> lff, lfp;
    lff.reserve(nf * 12);
    for (int f = 0; f < nf; ++f) {
      const int c[3] = {mesh.triangles[f].x, mesh.triangles[f].y, mesh.triangles[f].z};
      for (int k = 0; k < 3; ++k) {
        const int i = c[(k + 1) % 3], j = c[(k + 2) % 3];
        const double w = cot[f][k];
        for (auto [a, b] : {std::pair{i, j}, std::pair{j, i}}) {
          if (reduced[a] < 0) continue;
          lff.emplace_back(reduced[a], reduced[a], w);
          if (reduced[b] >= 0) lff.emplace_back(reduced[a], reduced[b], -w);
          else lfp.emplace_back(reduced[a], 0, -w);
        }
      }
    }
    Eigen::SparseMatrix<double> laplacian(free_count, free_count);
    laplacian.setFromTriplets(lff.begin(), lff.end());
    if (options.energy == MapEnergy::SymmetricDirichlet) {
      precompute_symmetric_dirichlet(laplacian);
      report.precompute_ms += watch.milliseconds();
      return;
    }
    pinned_column.resize(free_count, 1);
    pinned_column.setFromTriplets(lfp.begin(), lfp.end());
    cholesky.compute(laplacian);
    if (cholesky.info() != Eigen::Success)
      throw InputError("ARAP: the Laplacian could not be factorized (degenerate triangles?)");
    report.factorizations = 1;
    report.precompute_ms += watch.milliseconds();
  }

  // Local step: the best rotation per triangle, in closed form for 2x2.
  void fit_rotations() {
    const int nf = mesh.face_count();
    for (int f = 0; f < nf; ++f) {
      const auto s = covariance(f, uv);
      rotation[f] = std::atan2(s[2] - s[1], s[0] + s[3]);
    }
  }

  // S = sum_k w_k du_k dx_k^T for triangle f, row-major (s00, s01, s10, s11).
  std::array<double, 4> covariance(int f, const std::vector<glm::dvec2>& u) const {
    const int c[3] = {mesh.triangles[f].x, mesh.triangles[f].y, mesh.triangles[f].z};
    std::array<double, 4> s{0, 0, 0, 0};
    for (int k = 0; k < 3; ++k) {
      const int i = (k + 1) % 3, j = (k + 2) % 3;
      const glm::dvec2 du = u[c[i]] - u[c[j]], dx = flat[f][i] - flat[f][j];
      const double w = cot[f][k];
      s[0] += w * du.x * dx.x, s[1] += w * du.x * dx.y;
      s[2] += w * du.y * dx.x, s[3] += w * du.y * dx.y;
    }
    return s;
  }

  // ARAP energy with the best rotations for u, plus the barrier
  //   barrier_weight * sum_t A_t |J_t^-1|_F^2,
  // the inverse half of the symmetric Dirichlet energy: negligible on a good map, infinite at a
  // collapsed triangle. ARAP alone is finite at collapse, so without it the injective line
  // search drives triangles towards zero area. +inf if any triangle is not positive.
  double total_energy(const std::vector<glm::dvec2>& u) const {
    double e = 0;
    const int nf = mesh.face_count();
    for (int f = 0; f < nf; ++f) {
      const int c[3] = {mesh.triangles[f].x, mesh.triangles[f].y, mesh.triangles[f].z};
      const glm::dvec2 e1 = u[c[1]] - u[c[0]], e2 = u[c[2]] - u[c[0]];
      const double det2 = detail::cross2(e1, e2);  // twice the 2D area
      if (!(det2 > 0)) return std::numeric_limits<double>::infinity();
      double squares = 0;
      for (int k = 0; k < 3; ++k) {
        const int i = (k + 1) % 3, j = (k + 2) % 3;
        const glm::dvec2 du = u[c[i]] - u[c[j]], dx = flat[f][i] - flat[f][j];
        squares += cot[f][k] * (glm::dot(du, du) + glm::dot(dx, dx));
      }
      const auto s = covariance(f, u);
      e += squares - 2 * std::hypot(s[0] + s[3], s[2] - s[1]);
      // |J^-1|_F^2 = |J|_F^2 / det(J)^2; with J = E_uv E_x^-1, det J = A_2D / A_3D and
      // |J|_F^2 = sum_k cot_k |du_k|^2 / (2 A_3D).
      double dirichlet = 0;
      for (int k = 0; k < 3; ++k) {
        const int i = (k + 1) % 3, j = (k + 2) % 3;
        const glm::dvec2 du = u[c[i]] - u[c[j]];
        dirichlet += cot[f][k] * glm::dot(du, du);
      }
      const double a3 = area3[f], det_j = 0.5 * det2 / a3;
      e += options.barrier_weight * a3 * (dirichlet / (2 * a3)) / (det_j * det_j);
    }
    return e;
  }

  // The fixed Laplacian L is the proxy Hessian (Kovalsky et al. 2016): the step solves
  // L d = -1/2 grad E. For ARAP alone this is the classic global step; the barrier's gradient
  // enters the right-hand side, so the step stays a descent direction of the energy the line
  // search measures, without refactorizing.
  void add_barrier_gradient(Eigen::MatrixX2d& rhs) const {
    const int nf = mesh.face_count();
    for (int f = 0; f < nf; ++f) {
      const int c[3] = {mesh.triangles[f].x, mesh.triangles[f].y, mesh.triangles[f].z};
      // M = [u1-u0, u2-u0], X = [x1-x0, x2-x0]; barrier = w A |X M^-1|_F^2, whose gradient in
      // M is -2 w A M^-T G M^-1 M^-T with G = X^T X.
      const glm::dvec2 m0 = uv[c[1]] - uv[c[0]], m1 = uv[c[2]] - uv[c[0]];
      const double det = m0.x * m1.y - m1.x * m0.y;
      if (!(det > 0)) continue;
      // M^-1 (row-major) for M with columns m0, m1.
      const double i00 = m1.y / det, i01 = -m1.x / det, i10 = -m0.y / det, i11 = m0.x / det;
      const glm::dvec2 x0 = flat[f][1] - flat[f][0], x1 = flat[f][2] - flat[f][0];
      const double g00 = glm::dot(x0, x0), g01 = glm::dot(x0, x1), g11 = glm::dot(x1, x1);
      // P = M^-T G M^-1 (symmetric), then grad = -2 w A P M^-T.
      const double a00 = i00 * g00 + i10 * g01, a01 = i00 * g01 + i10 * g11;  // M^-T G, row 0
      const double a10 = i01 * g00 + i11 * g01, a11 = i01 * g01 + i11 * g11;  // row 1
      const double p00 = a00 * i00 + a01 * i10, p01 = a00 * i01 + a01 * i11;
      const double p10 = a10 * i00 + a11 * i10, p11 = a10 * i01 + a11 * i11;
      const double k = -2 * options.barrier_weight * face_weight[f] * area3[f];
      // grad_M = k * P * M^-T; M^-T = [[i00, i10], [i01, i11]].
      const double d00 = k * (p00 * i00 + p01 * i01), d01 = k * (p00 * i10 + p01 * i11);
      const double d10 = k * (p10 * i00 + p11 * i01), d11 = k * (p10 * i10 + p11 * i11);
      const glm::dvec2 grad1(d00, d10), grad2(d01, d11), grad0 = -(grad1 + grad2);
      const glm::dvec2 grads[3] = {grad0, grad1, grad2};
      for (int k2 = 0; k2 < 3; ++k2) {
        const int r = reduced[c[k2]];
        if (r < 0) continue;
        rhs(r, 0) -= 0.5 * grads[k2].x;
        rhs(r, 1) -= 0.5 * grads[k2].y;
      }
    }
  }

  void global_step() {
    const int free_count = static_cast<int>(cholesky.rows());
    Eigen::MatrixX2d rhs = Eigen::MatrixX2d::Zero(free_count, 2);
    const int nf = mesh.face_count();
    for (int f = 0; f < nf; ++f) {
      const int c[3] = {mesh.triangles[f].x, mesh.triangles[f].y, mesh.triangles[f].z};
      const double cs = std::cos(rotation[f]), sn = std::sin(rotation[f]);
      for (int k = 0; k < 3; ++k) {
        const int i = (k + 1) % 3, j = (k + 2) % 3;
        const glm::dvec2 dx = flat[f][i] - flat[f][j];
        const glm::dvec2 r = cot[f][k] * glm::dvec2(cs * dx.x - sn * dx.y, sn * dx.x + cs * dx.y);
        if (reduced[c[i]] >= 0) rhs(reduced[c[i]], 0) += r.x, rhs(reduced[c[i]], 1) += r.y;
        if (reduced[c[j]] >= 0) rhs(reduced[c[j]], 0) -= r.x, rhs(reduced[c[j]], 1) -= r.y;
      }
    }
    if (options.barrier_weight > 0) add_barrier_gradient(rhs);
    const glm::dvec2 pinned = uv[pinned_vertex];
    for (Eigen::SparseMatrix<double>::InnerIterator it(pinned_column, 0); it; ++it) {
      rhs(it.row(), 0) -= it.value() * pinned.x;
      rhs(it.row(), 1) -= it.value() * pinned.y;
    }
    const Eigen::MatrixX2d solution = cholesky.solve(rhs);
    target = uv;
    for (int v = 0; v < mesh.vertex_count(); ++v)
      if (reduced[v] >= 0) target[v] = {solution(reduced[v], 0), solution(reduced[v], 1)};
  }

  // ---- Symmetric Dirichlet by SLIM (Rabinovich et al. 2017): a proxy reweighted by each
  // triangle's singular values, so a triangle squeezed a millionfold expands in a few steps.
  std::vector<std::array<double, 6>> gradient_op;  // #F G = Dx^-T [-1 1 0; -1 0 1], row-major 2x3
  std::vector<std::array<int, 9>> slot;            // #F where each corner pair's entry sits in `proxy`
  Eigen::SparseMatrix<double> proxy;               // the Laplacian's pattern, SLIM's weights
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> proxy_cholesky;
  double total_weighted_area = 0;
  int since_refresh = std::numeric_limits<int>::max();
  double last_decrease = 1;
  std::vector<double> recent_energies;  // after each iteration
  // The proxy is refactorized every iteration while the energy falls by more than 1% a step, and
  // else serves up to four steps in all (measured on the bunny head: the same map with about half
  // the factorizations).
  static constexpr int kProxyReuse = 4;
  static constexpr double kFastDecrease = 1e-2;

  glm::dmat2 jacobian(int f, const std::vector<glm::dvec2>& u) const {
    const auto& t = mesh.triangles[f];
    const auto& g = gradient_op[f];
    const glm::dvec2 p[3] = {u[t.x], u[t.y], u[t.z]};
    glm::dmat2 j(0.0);  // j[c][r] = d u_r / d x_c
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 2; ++c) j[c] += g[c * 3 + k] * p[k];
    return j;
  }

  double symmetric_dirichlet(const std::vector<glm::dvec2>& u) const {
    double e = 0;
    for (int f = 0; f < mesh.face_count(); ++f) {
      const glm::dmat2 j = jacobian(f, u);
      const double det = glm::determinant(j);
      if (!(det > 0)) return std::numeric_limits<double>::infinity();
      const double fro = glm::dot(j[0], j[0]) + glm::dot(j[1], j[1]);
      e += face_weight[f] * area3[f] * fro * (1 + 1 / (det * det));
    }
    return e / total_weighted_area;
  }
  void precompute_symmetric_dirichlet(const Eigen::SparseMatrix<double>& laplacian) {
    const int nf = mesh.face_count();
    gradient_op.resize(nf);
    total_weighted_area = 0;
    for (int f = 0; f < nf; ++f) {
      const glm::dvec2 x1 = flat[f][1] - flat[f][0], x2 = flat[f][2] - flat[f][0];
      const double det = detail::cross2(x1, x2);
      const double i00 = x2.y / det, i01 = -x2.x / det, i10 = -x1.y / det, i11 = x1.x / det;  // Dx^-1
      gradient_op[f] = {-(i00 + i10), i00, i10, -(i01 + i11), i01, i11};  // Dx^-T [-1 1 0; -1 0 1]
      total_weighted_area += face_weight[f] * area3[f];
    }
    proxy = laplacian;
    proxy.makeCompressed();
    const auto find = [&](int row, int col) {
      const int* begin = proxy.innerIndexPtr() + proxy.outerIndexPtr()[col];
      const int* end = proxy.innerIndexPtr() + proxy.outerIndexPtr()[col + 1];
      return int(std::lower_bound(begin, end, row) - proxy.innerIndexPtr());
    };
    slot.resize(nf);
    for (int f = 0; f < nf; ++f) {
      const int c[3] = {mesh.triangles[f].x, mesh.triangles[f].y, mesh.triangles[f].z};
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l)
          slot[f][3 * k + l] = reduced[c[k]] < 0 || reduced[c[l]] < 0 ? -1 : find(reduced[c[k]], reduced[c[l]]);
    }
    proxy_cholesky.analyzePattern(proxy);
  }

  // One step: the direction solves P d = -grad E / 2. P is SLIM's proxy made isotropic (each
  // triangle's Laplacian weighted by the mean of its two squared SLIM weights), so u and v share
  // one factorization of the Laplacian's pattern, an eighth of the work of the 2x2-block proxy
  // for the same energy in about the same time on the bunny head, and less time from 48k faces.
  // The exact gradient keeps it a descent direction, also between refreshes of P.
  void symmetric_dirichlet_step(bool refresh) {
    const int nf = mesh.face_count();
    if (refresh) std::fill(proxy.valuePtr(), proxy.valuePtr() + proxy.nonZeros(), 0.0);
    Eigen::MatrixX2d gradient = Eigen::MatrixX2d::Zero(proxy.rows(), 2);
    for (int f = 0; f < nf; ++f) {
      const glm::dmat2 j = jacobian(f, uv);
      // J = [[a, b], [c, d]] (rows u, v); closed-form 2x2 SVD J = U diag(s1, s2) V^T.
      const double a = j[0].x, b = j[1].x, c = j[0].y, d = j[1].y;
      const double e = 0.5 * (a + d), ff = 0.5 * (a - d), g = 0.5 * (c + b), h = 0.5 * (c - b);
      const double q = std::sqrt(e * e + h * h), r = std::sqrt(ff * ff + g * g);
      // s2 from the determinant: q - r cancels where s1 / s2 is large. det > 0: the map is injective.
      const double s1 = q + r, s2 = glm::determinant(j) / s1;
      // The closest rotation R = rot(beta) with (cos, sin) beta = (e, h) / q; U = rot(phi) with
      // 2 phi = alpha + beta, (cos, sin) alpha = (f, g) / r (any alpha when r = 0: then s1 = s2).
      const double cr = e / q, sr = h / q;
      const double ca = r > 0 ? ff / r : 1, sa = r > 0 ? g / r : 0;
      const double cos2 = ca * cr - sa * sr, sin2 = sa * cr + ca * sr;
      // SLIM's weights for the symmetric Dirichlet energy, squared: (s + 1)(s^2 + 1) / s^3.
      const auto weight2 = [](double s) { return (s + 1) * (s * s + 1) / (s * s * s); };
      const double w1 = weight2(s1), w2 = weight2(s2);
      const double mean = 0.5 * (w1 + w2), half = 0.5 * (w1 - w2);
      const double m00 = mean + half * cos2, m01 = half * sin2, m11 = mean - half * cos2;  // W^2
      // grad E / 2 in J: W^2 (J - R) = U diag(s - s^-3) V^T, R = [[cr, -sr], [sr, cr]].
      const double d00 = a - cr, d01 = b + sr, d10 = c - sr, d11 = d - cr;
      const double g00 = m00 * d00 + m01 * d10, g01 = m00 * d01 + m01 * d11;
      const double g10 = m01 * d00 + m11 * d10, g11 = m01 * d01 + m11 * d11;
      const double scale = face_weight[f] * area3[f];
      const auto& gop = gradient_op[f];
      const int corner[3] = {mesh.triangles[f].x, mesh.triangles[f].y, mesh.triangles[f].z};
      for (int k = 0; k < 3; ++k) {
        const int rk = reduced[corner[k]];
        if (rk < 0) continue;  // the pinned vertex
        gradient(rk, 0) += scale * (gop[k] * g00 + gop[3 + k] * g01);
        gradient(rk, 1) += scale * (gop[k] * g10 + gop[3 + k] * g11);
        if (!refresh) continue;
        for (int l = 0; l < 3; ++l)
          if (slot[f][3 * k + l] >= 0)
            proxy.valuePtr()[slot[f][3 * k + l]] += scale * mean * (gop[k] * gop[l] + gop[3 + k] * gop[3 + l]);
      }
    }
    if (refresh) {
      proxy_cholesky.factorize(proxy);
      if (proxy_cholesky.info() != Eigen::Success)
        throw InputError("map: the symmetric Dirichlet proxy could not be factorized (degenerate triangles?)");
      ++report.factorizations;
    }
    const Eigen::MatrixX2d step = proxy_cholesky.solve(gradient);
    target = uv;
    for (int v = 0; v < mesh.vertex_count(); ++v)
      if (reduced[v] >= 0) target[v] -= glm::dvec2(step(reduced[v], 0), step(reduced[v], 1));
  }

  double map_energy(const std::vector<glm::dvec2>& u) const {
    return options.energy == MapEnergy::SymmetricDirichlet ? symmetric_dirichlet(u) : total_energy(u);
  }

  // Step in (0, 1] along target - uv: short of any triangle's collapse, lowering the total
  // energy, and keeping the boundary simple. 0 when no such step is found.
  double line_search() {
    double limit = std::numeric_limits<double>::infinity();
    for (const auto& t : mesh.triangles) {
      const glm::dvec2 e1 = uv[t.y] - uv[t.x], e2 = uv[t.z] - uv[t.x];
      const glm::dvec2 f1 = (target[t.y] - uv[t.y]) - (target[t.x] - uv[t.x]);
      const glm::dvec2 f2 = (target[t.z] - uv[t.z]) - (target[t.x] - uv[t.x]);
      limit = std::min(limit, first_collapse(e1, e2, f1, f2));
    }
    double alpha = std::min(1.0, 0.9 * limit);
    for (int halvings = 0; halvings < 40; ++halvings, alpha *= 0.5) {
      for (size_t v = 0; v < uv.size(); ++v) trial[v] = uv[v] + alpha * (target[v] - uv[v]);
      const double e = map_energy(trial);
      if (!(e < energy)) continue;
      if (count_loop_self_intersections(mesh.outer_loop(), trial) != 0) continue;
      trial_energy = e;
      return alpha;
    }
    return 0;
  }

  bool iterate(int max_iterations) {
    const Stopwatch watch;
    bool converged = false;
    trial.resize(uv.size());
    if (report.iterations == 0 && recent_energies.empty()) {
      energy = report.initial_energy = map_energy(uv);
      // No step can lower an infinite or NaN energy: it would stop at once as "converged".
      if (!std::isfinite(energy))
        throw InputError("map: the start map's energy is not finite (a triangle of zero area on the surface)");
      recent_energies.push_back(energy);  // the stopping window counts from the start
    }
    const bool dirichlet = options.energy == MapEnergy::SymmetricDirichlet;
    for (int it = 0; it < max_iterations; ++it) {
      bool refreshed = false;
      if (dirichlet) {
        // A fresh proxy while the energy falls fast; the last one reused for a few steps after.
        refreshed = since_refresh >= kProxyReuse || last_decrease > kFastDecrease;
        since_refresh = refreshed ? 1 : since_refresh + 1;
        symmetric_dirichlet_step(refreshed);
      } else {
        fit_rotations();
        global_step();
      }
      double alpha = 1;
      if (options.injective || dirichlet) {
        alpha = line_search();
        if (alpha == 0 && dirichlet && !refreshed) {
          since_refresh = kProxyReuse;  // a stale proxy found no step: try a fresh one
          --it;                         // which is bounded: a fresh proxy's failure ends the loop
          continue;
        }
        if (alpha > 0 && alpha < 1) ++report.blocked_steps;
        if (alpha == 0) {
          converged = true;  // no bijective step lowers the energy: a constrained minimum
          break;
        }
        uv.swap(trial);
      } else {
        uv = target;
        trial_energy = total_energy(uv);
      }
      ++report.iterations;
      const double previous = energy;
      energy = trial_energy;
      last_decrease = std::isfinite(previous) ? (previous - energy) / previous : 1.0;
      // Converged when the energy fell by less than `tolerance` of itself per iteration over the
      // last kStopWindow iterations (one short step alone does not stop it).
      recent_energies.push_back(energy);
      const std::size_t window = MapOptions::kStopWindow;
      if (recent_energies.size() > window) {
        const double before = recent_energies[recent_energies.size() - 1 - window];
        const double tolerance = options.tolerance > 0 ? options.tolerance
                                 : dirichlet               ? MapOptions::kSymmetricDirichletTolerance
                                                           : MapOptions::kArapTolerance;
        if (before - energy <= window * tolerance * energy) {
          converged = true;
          break;
        }
      }
    }
    report.final_energy = energy;
    report.solve_ms += watch.milliseconds();
    return converged;
  }
};

MapSolver::MapSolver(const SurfaceMesh& mesh, const MapOptions& options)
    : impl_(std::make_unique<Impl>(mesh, options)) {
  auto& s = *impl_;
  const Stopwatch watch;
  const SurfaceMesh& disk = s.mesh;
  if (options.start != MapStart::Tutte) {
    std::vector<glm::dvec2> start = lscm(disk);
    const bool usable = count_flipped_triangles(disk, start) == 0 &&
                        count_loop_self_intersections(disk.outer_loop(), start) == 0;
    if (usable) {
      s.uv = std::move(start);
      s.report.start_used = MapStart::Lscm;
    } else if (options.start == MapStart::Lscm) {
      throw InputError("map: the LSCM start map is not bijective on this surface; use the Tutte start");
    }
  }
  if (s.uv.empty()) {
    s.uv = tutte_embedding(disk);
    s.report.start_used = MapStart::Tutte;
  }
  // Symmetric Dirichlet is not scale-free: it starts at the surface's area.
  if (options.energy == MapEnergy::SymmetricDirichlet) detail::scale_to_surface_area(disk, s.uv);
  s.report.precompute_ms = watch.milliseconds();
  s.precompute();
}

MapSolver::~MapSolver() = default;
MapSolver::MapSolver(MapSolver&&) noexcept = default;
MapSolver& MapSolver::operator=(MapSolver&&) noexcept = default;

bool MapSolver::iterate(int max_iterations) { return impl_->iterate(max_iterations); }
const std::vector<glm::dvec2>& MapSolver::uv() const { return impl_->uv; }
double MapSolver::energy() const { return impl_->energy; }
const MapReport& MapSolver::report() const { return impl_->report; }

Parameterization finish_parameterization(const SurfaceMesh& mesh, const MapSolver& solver) {
  Parameterization result;
  result.uv = solver.uv();
  result.uv.resize(mesh.vertex_count());  // the holes' patches are dropped
  result.report = solver.report();
  const detail::UvRescale rescale = detail::scale_to_surface_area(mesh, result.uv);
  // close_holes puts one centre vertex per hole after the surface's vertices.
  for (std::size_t h = 0; h < std::size_t(mesh.hole_count()); ++h)
    result.hole_centres.push_back(rescale(solver.uv()[mesh.vertex_count() + h]));
  result.quality = measure_map(mesh, result.uv);
  return result;
}

namespace {
// Each enumerator's words and report.json key, in the enum's order.
struct Naming {
  std::string_view name, key;
};
constexpr Naming kEnergyNaming[] = {{"symmetric Dirichlet", "symmetric_dirichlet"}, {"ARAP", "arap"}};
constexpr Naming kStartNaming[] = {{"auto", "auto"}, {"LSCM", "lscm"}, {"Tutte", "tutte"}};
}  // namespace

std::string_view map_energy_name(MapEnergy energy) { return kEnergyNaming[int(energy)].name; }
std::string_view map_energy_key(MapEnergy energy) { return kEnergyNaming[int(energy)].key; }
std::string_view map_start_name(MapStart start) { return kStartNaming[int(start)].name; }
std::string_view map_start_key(MapStart start) { return kStartNaming[int(start)].key; }

std::string map_method_name(const MapReport& report) {
  if (report.planar) return "the projection onto its plane (the surface is flat)";
  return std::string(map_energy_name(report.energy)) + " from " + std::string(map_start_name(report.start_used));
}
std::string_view map_method_key(const MapReport& report) { return report.planar ? "planar" : map_energy_key(report.energy); }

MapOptions map_options_for(const SurfaceMesh& mesh, MapPiece piece) {
  MapOptions options;
  if (piece == MapPiece::Chart || mesh.boundary_loops.size() != 1) options.energy = MapEnergy::Arap;
  return options;
}

Parameterization parameterize_surface(const SurfaceMesh& mesh, const MapOptions& options) {
  if (options.start == MapStart::Auto)
    if (std::optional<Parameterization> flat = planar_parameterization(mesh)) return std::move(*flat);
  MapSolver solver(mesh, options);
  solver.iterate(options.max_iterations);
  return finish_parameterization(mesh, solver);
}

std::string map_progress_text(int done, int max, double energy) {
  char text[96];
  std::snprintf(text, sizeof text, "%d / %d iterations, energy %.6g", done, max, energy);
  return text;
}

std::optional<Parameterization> parameterize_surface(const SurfaceMesh& mesh, const MapOptions& options,
                                                  const std::function<void(int done, int max, double energy)>& progress,
                                                  const std::function<bool()>& stop) {
  constexpr int kIterationsPerChunk = 5;  // a few per second on a 1M-face mesh
  const auto stopped = [&] { return stop && stop(); };
  if (options.start == MapStart::Auto)
    if (std::optional<Parameterization> flat = planar_parameterization(mesh)) return flat;
  MapSolver solver(mesh, options);
  while (solver.report().iterations < options.max_iterations) {
    if (stopped()) return std::nullopt;
    const int chunk = std::min(kIterationsPerChunk, options.max_iterations - solver.report().iterations);
    if (solver.iterate(chunk)) break;
    if (progress) progress(solver.report().iterations, options.max_iterations, solver.energy());
  }
  if (stopped()) return std::nullopt;
  return finish_parameterization(mesh, solver);
}

}  // namespace paver
