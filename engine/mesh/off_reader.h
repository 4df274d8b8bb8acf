#pragma once
// OFF, as text ('[ST][C][N]OFF' alone on line 1, then '<vertices> <faces> <edges>', the vertex
// lines and the face lines '<n> <i1> ... <in>', indices from 0) and binary ('[ST][C][N]OFF BINARY'
// on line 1, then 4-byte counts, float coordinates and 4-byte face sizes and indices), in either
// byte order: Geomview's big-endian or OpenMesh's little-endian, whichever order's counts fit the
// file.
#include "mesh/polygon_soup.h"

#include <string>
#include <string_view>

namespace paver {

// Refuses with an InputError "<source>: line N: ..." (text) or "<source>: byte offset N: ..."
// (binary) what it cannot read. Binary counts are checked against the file length before
// anything is allocated.
PolygonSoup read_off(std::string_view bytes, const std::string& source);

}  // namespace paver
