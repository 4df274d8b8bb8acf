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
#include <string>

namespace paver {

// Larger files are refused before they are read: no surface Paver can pave needs more.
constexpr std::uintmax_t kMaxMeshFileBytes = std::uintmax_t(1) << 30;  // 1 GiB

// `source` names the file in error messages (InputError "<source>: ..."), e.g. its path.
PolygonSoup read_mesh_file(const std::filesystem::path& path, const std::string& source);

}  // namespace paver
