#pragma once
// Checks a polygon soup and repairs it into the SurfaceMesh Paver paves: triangulation, the
// largest connected component, manifoldness, consistent orientation, and no handles (a disk, a
// surface with holes, or a closed one). What it repairs is reported as warnings; what it cannot is an InputError.
#include "mesh/mesh_loader.h"

#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace paver {

// What check_and_repair may do to vertices: join those at one position and split bowties (a user's
// file), or neither (a mesh Paver made whose vertex numbers the caller keeps, a closed surface's
// chart: there a bowtie is refused as non-manifold, and the vertices come out as they went in).
enum class VertexRepair { JoinAndSplit, None };

// `source` names the mesh in messages; `collapsed_faces` are faces the reader already left out
// (PolygonSoup::collapsed_faces), counted with the degenerate ones.
LoadedSurface check_and_repair(std::vector<glm::dvec3> positions, const std::vector<std::vector<int>>& polygons,
                               const std::string& source, int collapsed_faces,
                               VertexRepair repair = VertexRepair::JoinAndSplit);

}  // namespace paver
