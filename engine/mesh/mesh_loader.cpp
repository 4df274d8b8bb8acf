// Surface loading in two halves: reading a file into a polygon soup with the strict reader for its
// format (read_mesh_file.h), and check_and_repair (mesh_repair.h), which makes the SurfaceMesh
// Paver paves out of the soup, or refuses it saying why.
#include "mesh/mesh_loader.h"

#include "core/float32_rounding.h"
#include "mesh/mesh_repair.h"
#include "mesh/read_mesh_file.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

#include <utility>

namespace paver {

LoadedSurface make_surface(std::vector<glm::dvec3> positions, const std::vector<std::vector<int>>& polygons,
                           const std::string& source) {
  return check_and_repair(std::move(positions), polygons, source, 0);
}

namespace {

// A surface near the origin for its size (no farther than 16 times its size) is rounded to
// float32, as Paver's readers always read it: float32 then keeps it within 1e-6 of its size, so
// nothing is lost, and a run repeats earlier versions' results bit for bit (the adaptive pattern
// on a scan moves by a percent with any change at the rounding level). A surface farther out, a
// facade in survey coordinates, keeps the doubles it was written with.
void round_near_origin_to_float32(std::vector<glm::dvec3>& positions) {
  if (positions.empty()) return;
  glm::dvec3 low(positions.front()), high(low);
  double largest = 0;
  for (const glm::dvec3& p : positions) {
    low = glm::min(low, p), high = glm::max(high, p);
    largest = std::max({largest, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  }
  if (!(largest * std::ldexp(1.0, -24) <= 1e-6 * glm::length(high - low))) return;
  for (glm::dvec3& p : positions)
    for (int axis = 0; axis < 3; ++axis) p[axis] = rounded_to_float32(p[axis]);
}

}  // namespace

LoadedSurface load_surface(const std::filesystem::path& path) {
  const std::string source = path.string();
  PolygonSoup soup = read_mesh_file(path, source);
  round_near_origin_to_float32(soup.positions);
  return check_and_repair(std::move(soup.positions), soup.polygons, source, soup.collapsed_faces);
}

}  // namespace paver
