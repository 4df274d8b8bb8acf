#pragma once
// What a mesh file holds, before any checks: vertex positions and polygons as index lists, in
// file order. The format readers produce it (read_mesh_file.h); check_and_repair (mesh_repair.h)
// makes the SurfaceMesh Paver paves out of it.
#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace paver {

struct PolygonSoup {
  // Finite, and single-precision values (see CoordinateReader in reader_support.h).
  std::vector<glm::dvec3> positions;
  // 0-based indices into `positions`, each valid; corners in file order.
  std::vector<std::vector<int>> polygons;
  // Faces the reader left out because fewer than 3 of their corners are distinct (an OBJ face
  // repeating a vertex, an STL facet whose corners weld together); reported as degenerate.
  int collapsed_faces = 0;
  // The named parts an OBJ's `g` and `o` lines put faces in (`--region` paves some of them): per
  // polygon an index into `group_sets`, each the names in force at that face; -1 for none. Empty
  // when the file names no parts.
  std::vector<std::vector<std::string>> group_sets;
  std::vector<int> polygon_group;
};

}  // namespace paver
