#include "map/boundary_walk.h"
#include "core/edge_key.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace paver {

BoundaryWalk::BoundaryWalk(const SurfaceMap& map) : map_(map) {
  const SurfaceMesh& mesh = map.mesh;
  for (int t = 0; t < mesh.face_count(); ++t)
    for (int k = 0; k < 3; ++k) triangle_on_[edge_key(mesh.triangles[t][k], mesh.triangles[t][(k + 1) % 3])] = t;
}

void BoundaryWalk::walk(int loop_index, double step,
                        const std::function<void(const BoundarySample&)>& visit) const {
  const SurfaceMesh& mesh = map_.mesh;
  const std::vector<int>& loop = mesh.boundary_loops[loop_index];
  double carried = 0;  // arc length since the last sample, carried across edges
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const int a = loop[k], b = loop[(k + 1) % loop.size()];
    const auto on = triangle_on_.find(edge_key(a, b));
    if (on == triangle_on_.end()) continue;
    const int t = on->second;
    const glm::dvec3 pa = mesh.positions[a], pb = mesh.positions[b];
    const double length = glm::length(pb - pa);
    if (!(length > 0)) continue;
    const glm::dvec3 along = (pb - pa) / length;
    int third = 0;
    for (int c = 0; c < 3; ++c)
      if (mesh.triangles[t][c] != a && mesh.triangles[t][c] != b) third = mesh.triangles[t][c];
    glm::dvec3 into = mesh.positions[third] - pa;
    into -= glm::dot(into, along) * along;
    if (!(glm::length(into) > 0)) continue;
    BoundarySample sample;
    sample.triangle = t;
    sample.into = glm::normalize(into);
    const glm::dvec2 ua = map_.uv[a], ub = nearest_image(map_, map_.uv[b], ua);
    for (double s = step - carried; s < length; s += step) {
      const double w = s / length;
      sample.position = pa * (1 - w) + pb * w;
      sample.uv = ua * (1 - w) + ub * w;
      visit(sample);
    }
    carried = std::fmod(carried + length, step);
  }
}

}  // namespace paver
