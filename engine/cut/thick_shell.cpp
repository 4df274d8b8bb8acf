#include "cut/thick_shell.h"

#include "core/input_error.h"
#include "core/number_text.h"

#include <cmath>
#include <cstdint>
#include <unordered_set>
#include <stdexcept>

namespace paver {

SurfaceMesh thick_shell(const SurfaceMesh& surface, const std::vector<glm::dvec3>& normals, double thickness) {
  if (!(thickness > 0) || !std::isfinite(thickness))
    throw InputError("--thickness " + number_text(thickness) + ": the metal needs a thickness above 0 (surface units)");
  if (normals.size() != surface.positions.size())
    throw std::invalid_argument("thick_shell: one normal per vertex is needed");
  std::vector<glm::dvec3> bottom(surface.positions.size());
  for (std::size_t v = 0; v < bottom.size(); ++v) bottom[v] = surface.positions[v] - thickness * normals[v];
  return shell_between(surface, bottom);
}

SurfaceMesh shell_between(const SurfaceMesh& surface, const std::vector<glm::dvec3>& bottom) {
  if (bottom.size() != surface.positions.size()) throw std::invalid_argument("shell_between: one bottom point per vertex");
  const int n = surface.vertex_count();
  SurfaceMesh shell;
  shell.positions = surface.positions;
  shell.positions.insert(shell.positions.end(), bottom.begin(), bottom.end());
  for (const glm::ivec3& t : surface.triangles) {
    shell.triangles.push_back(t);                                  // top, facing along the normals
    shell.triangles.emplace_back(t.x + n, t.z + n, t.y + n);       // bottom, facing against them
  }
  // A wall along every boundary edge, taken the way its one triangle runs it (a -> b): the wall
  // runs it b -> a, so orientation carries across to the walls and the bottom.
  std::unordered_set<std::uint64_t> directed;
  const auto key = [](int a, int b) { return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b); };
  for (const glm::ivec3& t : surface.triangles)
    for (int k = 0; k < 3; ++k) directed.insert(key(t[k], t[(k + 1) % 3]));
  for (const glm::ivec3& t : surface.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      if (directed.count(key(b, a))) continue;  // interior edge
      shell.triangles.emplace_back(b, a, a + n);
      shell.triangles.emplace_back(b, a + n, b + n);
    }
  return shell;
}

}  // namespace paver
