#include "map/lscm.h"

#include "core/input_error.h"
#include "mesh/surface_scaling.h"
#include "mesh/triangle_geometry.h"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <vector>

namespace paver {

std::vector<glm::dvec2> lscm(const SurfaceMesh& mesh) {
  const int n = mesh.vertex_count();
  const auto& loop = mesh.outer_loop();
  if (loop.size() < 3) throw InputError("LSCM needs a boundary loop of at least 3 vertices");

  // Pin the first boundary vertex and the boundary vertex farthest from it in 3D.
  const int pin_a = loop.front();
  int pin_b = loop[loop.size() / 2];
  double far = 0;
  for (int v : loop) {
    const double d = glm::length(mesh.positions[v] - mesh.positions[pin_a]);
    if (d > far) far = d, pin_b = v;
  }
  std::vector<glm::dvec2> uv(n, glm::dvec2(0));
  uv[pin_b] = {far, 0};

  // Unknown x = (u_0..u_{n-1}, v_0..v_{n-1}). Conformal energy
  //   E_C = 1/2 u^T Lw u + 1/2 v^T Lw v - A(u, v),
  // Lw the cotangent Laplacian (edge weight (cot a + cot b) / 2), A the signed area of the
  // boundary polygon. E_C = x^T Q x; minimise with the pinned entries fixed.
  std::vector<Eigen::Triplet<double>> q;
  q.reserve(mesh.triangles.size() * 24 + loop.size() * 4);
  for (const auto& t : mesh.triangles) {
    const int c[3] = {t.x, t.y, t.z};
    for (int k = 0; k < 3; ++k) {
      const int i = c[(k + 1) % 3], j = c[(k + 2) % 3];
      const double w = 0.25 * detail::cotangent(mesh.positions[c[k]], mesh.positions[i], mesh.positions[j]);
      for (int off : {0, n}) {
        q.emplace_back(i + off, i + off, w);
        q.emplace_back(j + off, j + off, w);
        q.emplace_back(i + off, j + off, -w);
        q.emplace_back(j + off, i + off, -w);
      }
    }
  }
  for (size_t e = 0; e < loop.size(); ++e) {
    const int i = loop[e], j = loop[(e + 1) % loop.size()];
    // A = 1/2 sum (u_i v_j - u_j v_i), split symmetrically.
    q.emplace_back(i, j + n, -0.25);
    q.emplace_back(j + n, i, -0.25);
    q.emplace_back(j, i + n, 0.25);
    q.emplace_back(i + n, j, 0.25);
  }
  std::vector<int> reduced(2 * n);
  std::vector<bool> pinned(2 * n, false);
  for (int p : {pin_a, pin_b}) pinned[p] = pinned[p + n] = true;
  int free_count = 0;
  for (int i = 0; i < 2 * n; ++i) reduced[i] = pinned[i] ? -1 : free_count++;
  auto value = [&](int i) { return i < n ? uv[i].x : uv[i - n].y; };

  std::vector<Eigen::Triplet<double>> qff;
  qff.reserve(q.size());
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(free_count);
  for (const auto& entry : q) {
    const int r = reduced[entry.row()];
    if (r < 0) continue;
    const int c = reduced[entry.col()];
    if (c >= 0) qff.emplace_back(r, c, entry.value());
    else rhs[r] -= entry.value() * value(entry.col());
  }
  Eigen::SparseMatrix<double> system(free_count, free_count);
  system.setFromTriplets(qff.begin(), qff.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(system);
  if (solver.info() != Eigen::Success)
    throw InputError("LSCM: the conformal energy could not be factorized (degenerate mesh?)");
  const Eigen::VectorXd x = solver.solve(rhs);
  for (int i = 0; i < 2 * n; ++i) {
    if (reduced[i] < 0) continue;
    if (i < n) uv[i].x = x[reduced[i]];
    else uv[i - n].y = x[reduced[i]];
  }
  detail::scale_to_surface_area(mesh, uv);
  return uv;
}

}  // namespace paver
