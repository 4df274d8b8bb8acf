#include "map/arap_parameterization.h"

#include <cstdio>

#include "core/input_error.h"
#include "map/hole_patches.h"
#include "map/lscm.h"
#include "map/tutte_embedding.h"
#include "mesh/surface_scaling.h"
#include "mesh/triangle_geometry.h"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>

namespace paver {
namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

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

struct ArapSolver::Impl {
  PatchedSurface patched;  // holes closed; the map of the real vertices is its first part
  const SurfaceMesh& mesh = patched.mesh;
  ArapOptions options;
  ArapReport report;
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

  Impl(const SurfaceMesh& m, const ArapOptions& o) : patched(close_holes(m)), options(o) {}

  void precompute() {
    const auto t0 = Clock::now();
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
    pinned_column.resize(free_count, 1);
    pinned_column.setFromTriplets(lfp.begin(), lfp.end());
    cholesky.compute(laplacian);
    if (cholesky.info() != Eigen::Success)
      throw InputError("ARAP: the Laplacian could not be factorized (degenerate triangles?)");
    report.precompute_ms += ms_since(t0);
  }

  std::vector<double> area3;                       // #F 3D triangle areas

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
      const double e = total_energy(trial);
      if (!(e < energy)) continue;
      if (count_loop_self_intersections(mesh.outer_loop(), trial) != 0) continue;
      trial_energy = e;
      return alpha;
    }
    return 0;
  }

  bool iterate(int max_iterations) {
    const auto t0 = Clock::now();
    bool converged = false;
    trial.resize(uv.size());
    if (report.iterations == 0) energy = report.initial_energy = total_energy(uv);
    for (int it = 0; it < max_iterations; ++it) {
      fit_rotations();
      global_step();
      double alpha = 1;
      if (options.injective) {
        alpha = line_search();
        if (alpha < 1) ++report.blocked_steps;
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
      if (std::isfinite(previous) && previous - energy <= options.tolerance * previous) {
        converged = true;
        break;
      }
    }
    report.final_energy = energy;
    report.solve_ms += ms_since(t0);
    return converged;
  }
};

ArapSolver::ArapSolver(const SurfaceMesh& mesh, const ArapOptions& options)
    : impl_(std::make_unique<Impl>(mesh, options)) {
  auto& s = *impl_;
  const auto t0 = Clock::now();
  const SurfaceMesh& disk = s.mesh;
  if (options.start != ArapStart::Tutte) {
    std::vector<glm::dvec2> start = lscm(disk);
    const bool usable = count_flipped_triangles(disk, start) == 0 &&
                        count_loop_self_intersections(disk.outer_loop(), start) == 0;
    if (usable) {
      s.uv = std::move(start);
      s.report.start_used = ArapStart::Lscm;
    } else if (options.start == ArapStart::Lscm) {
      throw InputError("ARAP: the LSCM start map is not bijective on this surface; use the Tutte start");
    }
  }
  if (s.uv.empty()) {
    s.uv = tutte_embedding(disk);
    s.report.start_used = ArapStart::Tutte;
  }
  s.report.precompute_ms = ms_since(t0);
  s.precompute();
}

ArapSolver::~ArapSolver() = default;
ArapSolver::ArapSolver(ArapSolver&&) noexcept = default;
ArapSolver& ArapSolver::operator=(ArapSolver&&) noexcept = default;

bool ArapSolver::iterate(int max_iterations) { return impl_->iterate(max_iterations); }
const std::vector<glm::dvec2>& ArapSolver::uv() const { return impl_->uv; }
double ArapSolver::energy() const { return impl_->energy; }
const ArapReport& ArapSolver::report() const { return impl_->report; }

Parameterization finish_parameterization(const SurfaceMesh& mesh, const ArapSolver& solver) {
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

Parameterization parameterize_arap(const SurfaceMesh& mesh, const ArapOptions& options) {
  ArapSolver solver(mesh, options);
  solver.iterate(options.max_iterations);
  return finish_parameterization(mesh, solver);
}

std::string arap_progress_text(int done, int max, double energy) {
  char text[96];
  std::snprintf(text, sizeof text, "ARAP %d / %d, energy %.6g", done, max, energy);
  return text;
}

std::optional<Parameterization> parameterize_arap(const SurfaceMesh& mesh, const ArapOptions& options,
                                                  const std::function<void(int done, int max, double energy)>& progress,
                                                  const std::function<bool()>& stop) {
  constexpr int kIterationsPerChunk = 5;  // a few per second on a 1M-face mesh
  const auto stopped = [&] { return stop && stop(); };
  ArapSolver solver(mesh, options);
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
