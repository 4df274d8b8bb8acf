#include "map/lifting.h"

#include <glm/geometric.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

namespace paver {

void LiftedPoints::resize(std::size_t n) {
  triangle.resize(n);
  position.resize(n);
  normal.resize(n);
  curvature.resize(n);
}

int lift_points(const SurfaceMap& map, std::span<const glm::dvec2> points, LiftedPoints& out) {
  const auto& tris = map.mesh.triangles;
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, points.size(), 1024), 0,
      [&](const tbb::blocked_range<std::size_t>& range, int outside) {
        for (std::size_t i = range.begin(); i != range.end(); ++i) {
          glm::dvec3 b;
          const int t = locate_on_map(map, points[i], b);
          out.triangle[i] = t;
          if (t < 0) {
            ++outside;
            continue;
          }
          const glm::ivec3 c = tris[t];
          out.position[i] = b.x * map.mesh.positions[c.x] + b.y * map.mesh.positions[c.y] + b.z * map.mesh.positions[c.z];
          out.normal[i] = glm::normalize(b.x * map.normals[c.x] + b.y * map.normals[c.y] + b.z * map.normals[c.z]);
          out.curvature[i] = b.x * map.curvature[c.x] + b.y * map.curvature[c.y] + b.z * map.curvature[c.z];
        }
        return outside;
      },
      [](int a, int b) { return a + b; });
}

glm::dvec2 map_point(const SurfaceMap& map, int triangle, glm::dvec3 bary) {
  const std::array<glm::dvec2, 3> c = triangle_uv(map, triangle);
  return bary.x * c[0] + bary.y * c[1] + bary.z * c[2];
}

}  // namespace paver
