// Surface loading in two halves: reading a file into a polygon soup with the strict reader for its
// format (read_mesh_file.h), and check_and_repair (mesh_repair.h), which makes the SurfaceMesh
// Paver paves out of the soup, or refuses it saying why.
#include "mesh/mesh_loader.h"

#include "core/float32_rounding.h"
#include "core/input_error.h"
#include "core/printable.h"
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

// The soup's faces in the parts named by `region` (every name checked against the file's), and
// only the vertices they use, in file order.
void keep_region(PolygonSoup& soup, const std::vector<std::string>& region, const std::string& source) {
  std::vector<std::string> names;
  for (const std::vector<std::string>& set : soup.group_sets)
    for (const std::string& name : set)
      if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  std::string listed;
  for (std::size_t i = 0; i < names.size() && i < 20; ++i) listed += (i ? ", " : "") + printable_cut(names[i], 40);
  if (names.size() > 20) listed += ", ...";
  for (const std::string& wanted : region) {
    if (names.empty())
      throw InputError(source + ": --region " + printable_cut(wanted, 40) +
                       ": the file names no parts (no OBJ 'g' or 'o' lines before its faces); pave it whole, or "
                       "export the part to pave as an OBJ group");
    if (std::find(names.begin(), names.end(), wanted) == names.end())
      throw InputError(source + ": --region " + printable_cut(wanted, 40) + ": the file has no part of that name; it has " +
                       listed);
  }
  std::vector<char> wanted_set(soup.group_sets.size(), 0);
  for (std::size_t g = 0; g < soup.group_sets.size(); ++g)
    for (const std::string& name : soup.group_sets[g])
      if (std::find(region.begin(), region.end(), name) != region.end()) wanted_set[g] = 1;
  std::vector<std::vector<int>> kept;
  for (std::size_t f = 0; f < soup.polygons.size(); ++f)
    if (soup.polygon_group[f] >= 0 && wanted_set[std::size_t(soup.polygon_group[f])]) kept.push_back(std::move(soup.polygons[f]));
  std::vector<int> index(soup.positions.size(), -1);
  std::vector<glm::dvec3> positions;
  for (std::vector<int>& polygon : kept)
    for (int& corner : polygon) {
      if (index[std::size_t(corner)] < 0) {
        index[std::size_t(corner)] = int(positions.size());
        positions.push_back(soup.positions[std::size_t(corner)]);
      }
      corner = index[std::size_t(corner)];
    }
  soup.positions = std::move(positions);
  soup.polygons = std::move(kept);
  soup.collapsed_faces = 0;  // faces left out of the region are no concern of this run
  soup.polygon_group.clear();
  soup.group_sets.clear();
}

}  // namespace

LoadedSurface load_surface(const std::filesystem::path& path, const std::vector<std::string>& region) {
  std::string source = path.string();
  PolygonSoup soup = read_mesh_file(path, source);
  if (!region.empty()) {
    keep_region(soup, region, source);
    std::string names;
    for (const std::string& name : region) names += (names.empty() ? "" : ",") + name;
    source += " (region " + printable_cut(names, 80) + ")";
  }
  round_near_origin_to_float32(soup.positions);
  return check_and_repair(std::move(soup.positions), soup.polygons, source, soup.collapsed_faces);
}

}  // namespace paver
