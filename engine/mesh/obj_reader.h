#pragma once
// Wavefront OBJ text: 'v x y z' vertices and 'f' faces whose corners are 'v', 'v/vt', 'v//vn' or
// 'v/vt/vn' (indices count from 1; negative ones count back from the last vertex defined above).
// Other lines (vt, vn, g, usemtl, ...) are skipped; '#' starts a comment.
#include "mesh/polygon_soup.h"

#include <string>
#include <string_view>

namespace paver {

// Refuses with an InputError "<source>: line N: ..." what it cannot read.
PolygonSoup read_obj(std::string_view text, const std::string& source);

}  // namespace paver
