#pragma once
// The input surface M = (V, F): an open, manifold, connected triangle mesh with one boundary loop.
#include <glm/vec3.hpp>

#include <vector>

namespace paver {

struct SurfaceMesh {
  std::vector<glm::dvec3> positions;  // #V vertex positions
  std::vector<glm::ivec3> triangles;  // #F vertex indices, consistently oriented
  std::vector<int> boundary_loop;     // ordered vertex indices of the one boundary loop

  int vertex_count() const { return static_cast<int>(positions.size()); }
  int face_count() const { return static_cast<int>(triangles.size()); }
};

// Total 3D area of the mesh.
double surface_area(const SurfaceMesh& mesh);

// Length of the diagonal of the axis-aligned bounding box.
double bounding_box_diagonal(const SurfaceMesh& mesh);

}  // namespace paver
