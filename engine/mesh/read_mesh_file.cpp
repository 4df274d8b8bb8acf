#include "mesh/read_mesh_file.h"

#include "core/regular_file.h"
#include "mesh/mesh_messages.h"
#include "mesh/obj_reader.h"
#include "mesh/off_reader.h"
#include "mesh/ply_reader.h"
#include "mesh/reader_support.h"
#include "mesh/stl_reader.h"

#include <algorithm>

namespace paver {
namespace {

using namespace mesh_detail;

std::string read_bytes(const std::filesystem::path& path, const std::string& source) {
  std::string bytes = read_regular_file(path, kMaxMeshFileBytes, source, "mesh file", "simplify the mesh first");
  if (bytes.empty()) fail(source, "the file is empty (0 bytes), so it contains no faces; export the surface again");
  return bytes;
}

}  // namespace

std::span<const std::string_view> mesh_file_extensions() {
  static constexpr std::string_view kExtensions[] = {".obj", ".off", ".ply", ".stl"};
  return kExtensions;
}

PolygonSoup read_mesh_file(const std::filesystem::path& path, const std::string& source) {
  const std::string extension = lowercase(path.extension().string());
  if (std::ranges::find(mesh_file_extensions(), extension) == mesh_file_extensions().end())
    fail(source, (extension.empty() ? std::string("has no file extension")
                                    : "unsupported file type '" + path.extension().string() + "'") +
                     "; Paver reads surfaces in OBJ, OFF, PLY (ASCII or binary) and STL (ASCII or binary) format "
                     "(.obj, .off, .ply, .stl)");
  PolygonSoup soup = [&] {
    const std::string bytes = read_bytes(path, source);
    if (extension == ".obj") return read_obj(bytes, source);
    if (extension == ".off") return read_off(bytes, source);
    if (extension == ".ply") return read_ply(bytes, source);
    return read_stl(bytes, source);
  }();
  // The binary formats' counts are checked against the file's size as they are read; the limits
  // on faces and their corners hold for every format.
  check_mesh_counts(source, static_cast<long long>(soup.positions.size()), static_cast<long long>(soup.polygons.size()));
  for (std::size_t f = 0; f < soup.polygons.size(); ++f)
    if (soup.polygons[f].size() > kMaxPolygonCorners)
      fail(source, "face " + std::to_string(f) + " (counting from 0) has " + std::to_string(soup.polygons[f].size()) +
                       " corners; Paver reads faces of up to " + std::to_string(kMaxPolygonCorners) +
                       ": triangulate it in the modeller");
  return soup;
}

}  // namespace paver
