#include "io/shape_table.h"
#include "design/design_keys.h"

#include "core/input_error.h"

#include <stdexcept>
#include <string>

namespace paver {
namespace {

void check_indices(const ShapeMesh& mesh) {
  const int n = static_cast<int>(mesh.positions.size());
  for (const glm::ivec3& t : mesh.triangles)
    if (t.x < 0 || t.y < 0 || t.z < 0 || t.x >= n || t.y >= n || t.z >= n)
      throw std::invalid_argument("ShapeMesh: a triangle refers to a vertex that does not exist");
}

}  // namespace

ShapeTable::ShapeTable(const Elements& elements, const ShapeMesh* custom, const std::filesystem::path& path) {
  for (std::size_t i = 0; i < elements.size(); ++i) {
    const ShapeKind kind = elements.shape[i];
    const auto slot = static_cast<std::size_t>(kind);
    if (mesh_[slot]) continue;
    if (kind == ShapeKind::Custom) {
      if (!custom)
        throw InputError("cannot write " + path.string() + ": element " + std::to_string(i) +
                         " uses the custom shape but none was loaded; set '" + key_path(Key::custom_shape) +
                         "' to a mesh file");
      mesh_[slot] = custom;
    } else {
      builtin_[slot] = make_builtin_shape(kind);
      mesh_[slot] = &builtin_[slot];
    }
    check_indices(*mesh_[slot]);
  }
}

}  // namespace paver
