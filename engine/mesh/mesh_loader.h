#pragma once
// Reads a surface (OBJ, OFF, PLY, STL with Paver's own readers), triangulates polygons and checks
// that it is something Paver can pave: finite coordinates, non-degenerate faces, manifold,
// connected, open with exactly one boundary loop. Throws InputError with a specific message otherwise.
#include "mesh/surface_mesh.h"

#include <filesystem>
#include <string>
#include <vector>

namespace paver {

struct LoadedSurface {
  SurfaceMesh mesh;
  std::vector<std::string> warnings;  // repairs made on the way (dropped faces, components)
  int dropped_degenerate_faces = 0;
  int dropped_components = 0;
};

// `region`: when given, only the faces of the OBJ parts (`g` or `o` lines) of these names are
// kept, their borders the surface's rims; a name the file does not have is an InputError that
// lists the names it has.
LoadedSurface load_surface(const std::filesystem::path& path, const std::vector<std::string>& region = {});

// The same checks and repairs for a mesh built in memory (vertices + polygon faces).
// `source` names it in error messages.
LoadedSurface make_surface(std::vector<glm::dvec3> positions,
                           const std::vector<std::vector<int>>& polygons,
                           const std::string& source);

}  // namespace paver
