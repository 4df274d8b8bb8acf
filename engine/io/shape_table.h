#pragma once
// The shapes a set of elements uses, each built once per export: every writer (PLY, OBJ, STL,
// glTF, 3MF) takes an element's mesh from here, so they all draw the same stone.
#include "elements/element_shape.h"
#include "elements/elements.h"

#include <array>
#include <cstddef>
#include <filesystem>

namespace paver {

class ShapeTable {
public:
  // `custom`: the design's custom shape, needed when an element uses ShapeKind::Custom; without it
  // that throws InputError naming `path` (the file being written). Throws std::invalid_argument
  // when a shape's triangle names a vertex it does not have.
  ShapeTable(const Elements& elements, const ShapeMesh* custom, const std::filesystem::path& path);

  ShapeTable(const ShapeTable&) = delete;  // mesh_ points into builtin_
  ShapeTable& operator=(const ShapeTable&) = delete;

  const ShapeMesh& operator[](ShapeKind kind) const { return *mesh_[static_cast<std::size_t>(kind)]; }
  // Whether some element uses `kind` (only those are built).
  bool used(ShapeKind kind) const { return mesh_[static_cast<std::size_t>(kind)] != nullptr; }

  static constexpr std::size_t kKinds = static_cast<std::size_t>(ShapeKind::Custom) + 1;

private:
  std::array<ShapeMesh, kKinds> builtin_;
  std::array<const ShapeMesh*, kKinds> mesh_{};
};

}  // namespace paver
