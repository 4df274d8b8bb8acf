#pragma once
// PLY (ascii, binary_little_endian, binary_big_endian 1.0): the vertex element's x, y and z, of
// any scalar type, and the face element's 'vertex_indices' (or 'vertex_index') list. Other
// elements and properties are skipped, lists included.
#include "mesh/polygon_soup.h"

#include <string>
#include <string_view>

namespace paver {

// Refuses with an InputError naming the line (ASCII) or the byte offset and element (binary)
// what it cannot read. Element counts and list lengths are checked against the file length
// before anything is allocated for them.
PolygonSoup read_ply(std::string_view bytes, const std::string& source);

}  // namespace paver
