// Surface loading in two halves: reading a file into a polygon soup with the strict reader for its
// format (read_mesh_file.h), and check_and_repair (mesh_repair.h), which makes the SurfaceMesh
// Paver paves out of the soup, or refuses it saying why.
#include "mesh/mesh_loader.h"

#include "mesh/mesh_repair.h"
#include "mesh/read_mesh_file.h"

#include <utility>

namespace paver {

LoadedSurface make_surface(std::vector<glm::dvec3> positions, const std::vector<std::vector<int>>& polygons,
                           const std::string& source) {
  return check_and_repair(std::move(positions), polygons, source, 0);
}

LoadedSurface load_surface(const std::filesystem::path& path) {
  const std::string source = path.string();
  PolygonSoup soup = read_mesh_file(path, source);
  return check_and_repair(std::move(soup.positions), soup.polygons, source, soup.collapsed_faces);
}

}  // namespace paver
