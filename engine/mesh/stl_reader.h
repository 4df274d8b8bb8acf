#pragma once
// STL, ASCII ('solid' ... 'facet normal' / 'outer loop' / 3 x 'vertex x y z' / 'endloop' /
// 'endfacet' ... 'endsolid') or binary (80-byte header, 4-byte triangle count, 50 bytes per
// triangle). A file is binary when its length is exactly 84 + 50 x its triangle count.
// STL stores each triangle's corners separately; corners at exactly the same position are welded
// into one vertex, so that the surface's topology can be checked.
#include "mesh/polygon_soup.h"

#include <string>
#include <string_view>

namespace paver {

// Refuses with an InputError naming the line (ASCII) or the byte offset and facet (binary) what it
// cannot read, and a binary file whose length does not match its triangle count (truncated).
PolygonSoup read_stl(std::string_view bytes, const std::string& source);

}  // namespace paver
