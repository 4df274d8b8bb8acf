#include "map/hole_patches.h"

#include <glm/geometric.hpp>

namespace paver {

PatchedSurface close_holes(const SurfaceMesh& surface) {
  PatchedSurface patched;
  patched.mesh.positions = surface.positions;
  patched.mesh.triangles = surface.triangles;
  patched.surface_vertices = surface.vertex_count();
  patched.surface_faces = surface.face_count();
  if (surface.boundary_loops.empty()) return patched;
  patched.mesh.boundary_loops = {surface.outer_loop()};
  for (size_t l = 1; l < surface.boundary_loops.size(); ++l) {
    const std::vector<int>& hole = surface.boundary_loops[l];
    glm::dvec3 centre(0);
    for (int v : hole) centre += surface.positions[v];
    centre /= double(hole.size());
    double radius = 0;
    for (int v : hole) radius += glm::length(surface.positions[v] - centre);
    radius /= double(hole.size());
    const int c = patched.mesh.vertex_count();
    patched.mesh.positions.push_back(centre);
    // The loop runs along its faces' orientation, so the fan's triangles run against it.
    for (size_t k = 0; k < hole.size(); ++k)
      patched.mesh.triangles.emplace_back(hole[(k + 1) % hole.size()], hole[k], c);
    patched.patch_hole_radius.insert(patched.patch_hole_radius.end(), hole.size(), radius);
  }
  return patched;
}

}  // namespace paver
