#pragma once
// Reads a mesh file (OBJ, OFF, PLY, STL; chosen by extension) into a polygon soup.
//
// Why our own readers: OpenMesh's hang or read uninitialised data on truncated or bad binaries
// (a binary OFF with bad counts loops with growing memory; a truncated binary STL or OFF is
// accepted with garbage coordinates), and we already had to pre-parse every format to report
// line numbers. One strict reader per format replaces both, and names the place of a problem.
#include "mesh/polygon_soup.h"

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

namespace paver {

// Larger files are refused before they are read: no surface Paver can pave needs more.
constexpr std::uintmax_t kMaxMeshFileBytes = std::uintmax_t(1) << 30;  // 1 GiB

// The file types read_mesh_file reads, lower case with the dot (".obj", ".off", ".ply", ".stl").
std::span<const std::string_view> mesh_file_extensions();

// `source` names the file in error messages (InputError "<source>: ..."), e.g. its path.
PolygonSoup read_mesh_file(const std::filesystem::path& path, const std::string& source);

}  // namespace paver
