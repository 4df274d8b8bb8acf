#include "mesh/mean_curvature.h"

#include "mesh/triangle_geometry.h"

#include <glm/geometric.hpp>

namespace paver {

std::vector<double> mean_curvature(const SurfaceMesh& mesh) {
  const int n = mesh.vertex_count();
  std::vector<glm::dvec3> laplacian(n, glm::dvec3(0));
  std::vector<double> area(n, 0);
  for (const auto& t : mesh.triangles) {
    const int c[3] = {t.x, t.y, t.z};
    const glm::dvec3 p[3] = {mesh.positions[t.x], mesh.positions[t.y], mesh.positions[t.z]};
    const double a = detail::triangle_area(p[0], p[1], p[2]);
    for (int k = 0; k < 3; ++k) {
      area[c[k]] += a / 3;
      // The angle at corner k weighs the opposite edge (i, j).
      const int i = (k + 1) % 3, j = (k + 2) % 3;
      const double w = detail::cotangent(p[k], p[i], p[j]);
      laplacian[c[i]] += w * (p[j] - p[i]);
      laplacian[c[j]] += w * (p[i] - p[j]);
    }
  }
  std::vector<bool> on_boundary(n, false);
  for (const std::vector<int>& loop : mesh.boundary_loops)
    for (int b : loop) on_boundary[b] = true;
  std::vector<double> h(n, 0);
  for (int v = 0; v < n; ++v)
    if (!on_boundary[v] && area[v] > 0) h[v] = glm::length(laplacian[v]) / (4 * area[v]);

  // Boundary vertices: mean of interior neighbours.
  std::vector<double> sum(n, 0);
  std::vector<int> count(n, 0);
  for (const auto& t : mesh.triangles) {
    const int c[3] = {t.x, t.y, t.z};
    for (int k = 0; k < 3; ++k)
      for (int o = 1; o < 3; ++o) {
        const int v = c[k], w = c[(k + o) % 3];
        if (on_boundary[v] && !on_boundary[w]) sum[v] += h[w], ++count[v];
      }
  }
  for (int v = 0; v < n; ++v)
    if (on_boundary[v] && count[v] > 0) h[v] = sum[v] / count[v];
  return h;
}

std::vector<glm::dvec3> vertex_normals(const SurfaceMesh& mesh) {
  std::vector<glm::dvec3> normals(mesh.positions.size(), glm::dvec3(0));
  for (const auto& t : mesh.triangles) {
    // The cross product's length is twice the area: area weighting for free.
    const glm::dvec3 n = glm::cross(mesh.positions[t.y] - mesh.positions[t.x], mesh.positions[t.z] - mesh.positions[t.x]);
    normals[t.x] += n, normals[t.y] += n, normals[t.z] += n;
  }
  for (auto& n : normals) {
    const double l = glm::length(n);
    n = l > 0 ? n / l : glm::dvec3(0, 0, 1);
  }
  return normals;
}

}  // namespace paver
