#include "map/tutte_embedding.h"

#include "core/input_error.h"
#include "mesh/triangle_geometry.h"

#include <Eigen/Sparse>
#include <Eigen/SparseLU>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace paver {

std::vector<glm::dvec2> tutte_embedding(const SurfaceMesh& mesh) {
  const int n = mesh.vertex_count();
  const auto& loop = mesh.outer_loop();
  std::vector<glm::dvec2> uv(n, glm::dvec2(0));

  // Boundary on a circle of the surface's area, spaced by arc length, counter-clockwise in
  // the loop's order (the loop follows the triangles' orientation).
  double perimeter = 0;
  for (size_t i = 0; i < loop.size(); ++i)
    perimeter += glm::length(mesh.positions[loop[(i + 1) % loop.size()]] - mesh.positions[loop[i]]);
  const double radius = std::sqrt(surface_area(mesh) / std::numbers::pi);
  std::vector<int> interior_index(n, 0);
  for (int b : loop) interior_index[b] = -1;
  double arc = 0;
  for (size_t i = 0; i < loop.size(); ++i) {
    const double angle = 2 * std::numbers::pi * arc / perimeter;
    uv[loop[i]] = radius * glm::dvec2(std::cos(angle), std::sin(angle));
    arc += glm::length(mesh.positions[loop[(i + 1) % loop.size()]] - mesh.positions[loop[i]]);
  }
  int interior = 0;
  for (int v = 0; v < n; ++v)
    if (interior_index[v] != -1) interior_index[v] = interior++;
  if (interior == 0) return uv;

  // Mean-value weights: w_ij = (tan(a/2) + tan(b/2)) / |x_i - x_j|, a and b the angles at i
  // beside edge ij. Always positive, unlike cotangent weights.
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(mesh.triangles.size() * 12);
  Eigen::VectorXd rhs_u = Eigen::VectorXd::Zero(interior), rhs_v = Eigen::VectorXd::Zero(interior);
  for (const auto& t : mesh.triangles) {
    const int c[3] = {t.x, t.y, t.z};
    for (int k = 0; k < 3; ++k) {
      const int i = c[k], j = c[(k + 1) % 3], l = c[(k + 2) % 3];
      const int row = interior_index[i];
      if (row < 0) continue;
      const glm::dvec3 eij = mesh.positions[j] - mesh.positions[i];
      const glm::dvec3 eil = mesh.positions[l] - mesh.positions[i];
      const double lij = glm::length(eij), lil = glm::length(eil);
      const double cos_angle = std::clamp(glm::dot(eij, eil) / (lij * lil), -1.0, 1.0);
      const double half_tan = std::tan(0.5 * std::acos(cos_angle));
      for (const auto& [other, len] : {std::pair{j, lij}, std::pair{l, lil}}) {
        const double w = half_tan / len;
        triplets.emplace_back(row, row, w);
        const int col = interior_index[other];
        if (col >= 0) {
          triplets.emplace_back(row, col, -w);
        } else {
          rhs_u[row] += w * uv[other].x;
          rhs_v[row] += w * uv[other].y;
        }
      }
    }
  }
  Eigen::SparseMatrix<double> system(interior, interior);
  system.setFromTriplets(triplets.begin(), triplets.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> solver;
  solver.compute(system);
  if (solver.info() != Eigen::Success)
    throw InputError("Tutte embedding: the Laplacian could not be factorized (degenerate mesh?)");
  const Eigen::VectorXd u = solver.solve(rhs_u), v = solver.solve(rhs_v);
  for (int vtx = 0; vtx < n; ++vtx)
    if (interior_index[vtx] >= 0) uv[vtx] = {u[interior_index[vtx]], v[interior_index[vtx]]};
  return uv;
}

}  // namespace paver
