#pragma once
// Whether a file's number format holds a pavement. A float32 value is within 2^-24 of its
// magnitude, so a facade in survey coordinates (5.4e6 m) loses up to a third of a metre, more than
// its discs' size: PLY and OBJ are then written in double precision, and STL (float32 by its
// format) gets a warning naming the error. 3MF places the elements about the piece's middle with
// 6 significant digits (lib3mf's printing; the middle itself is exact, io/threemf_export.cpp), so
// it rounds with the piece's size, and warns only for a piece very large for its elements. GLB is
// not affected: its vertices are relative to a node translation, which JSON holds in double.
#include "elements/elements.h"

#include <string>

namespace paver {

// The rounding a file may give an element, over the smallest element's diameter, before double
// precision (or a warning) is needed.
inline constexpr double kCoordinateTolerance = 1e-3;  // 1 um on a 1 mm stone

// The largest coordinate magnitude of the elements, their shapes included (within a diameter).
double largest_coordinate(const Elements& elements);

// True when float32 keeps every element within kCoordinateTolerance of the smallest diameter.
bool float32_holds(const Elements& elements);

// The warning when the STL file named (float32) or the 3MF file named (6 significant digits about
// the middle) would move the elements by more than kCoordinateTolerance of the smallest diameter;
// empty otherwise. Either name may be empty (not written).
std::string coordinate_rounding_warning(const Elements& elements, const std::string& stl_files,
                                        const std::string& threemf_files);

}  // namespace paver
