#pragma once
// The input surface M = (V, F): an open, manifold, connected, orientable triangle mesh of genus 0
// with one or more boundary loops: a disk has one, a band two, a pierced pendant one more per hole.
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <vector>

namespace paver {

struct SurfaceMesh {
  std::vector<glm::dvec3> positions;  // #V vertex positions
  std::vector<glm::ivec3> triangles;  // #F vertex indices, consistently oriented
  // Ordered vertex indices of each boundary loop, following the triangles' orientation. The
  // first is the outer loop (the longest, in 3D), which the map puts around the others; the
  // rest are holes.
  std::vector<std::vector<int>> boundary_loops;

  int vertex_count() const { return static_cast<int>(positions.size()); }
  int face_count() const { return static_cast<int>(triangles.size()); }
  int hole_count() const { return boundary_loops.empty() ? 0 : static_cast<int>(boundary_loops.size()) - 1; }
  const std::vector<int>& outer_loop() const { return boundary_loops.front(); }
};

// Total 3D area of the mesh.
double surface_area(const SurfaceMesh& mesh);

// Length of the diagonal of the axis-aligned bounding box.
double bounding_box_diagonal(const SurfaceMesh& mesh);

// Every boundary segment of every loop as (from, to) vertex indices, loop after loop, in the
// loops' direction: segment k of loop l joins loop[k] and loop[(k + 1) % size].
std::vector<glm::ivec2> boundary_segments(const SurfaceMesh& mesh);

// 3D length of one closed loop of vertex indices into `positions`.
double loop_length(const std::vector<glm::dvec3>& positions, const std::vector<int>& loop);

// Total 3D length of all boundary loops.
double boundary_length(const SurfaceMesh& mesh);

// Number of boundary vertices over all loops.
int boundary_vertex_count(const SurfaceMesh& mesh);

}  // namespace paver
