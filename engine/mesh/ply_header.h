#pragma once
// The header of a PLY file: its format, and the elements with their properties, in order.
// Read strictly, line by line, so that the data can be walked without guessing.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace paver::mesh_detail {

enum class PlyType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

size_t ply_type_size(PlyType type);
bool ply_type_is_integer(PlyType type);

struct PlyProperty {
  std::string name;
  bool list = false;
  PlyType type = PlyType::Float32;        // the scalar's type, or the list items' type
  PlyType count_type = PlyType::UInt8;    // lists: the type of the length prefix (an integer type)
};

struct PlyElement {
  std::string name;
  long long count = 0;
  std::vector<PlyProperty> properties;
};

struct PlyHeader {
  enum class Format { Ascii, BinaryLittleEndian, BinaryBigEndian } format = Format::Ascii;
  std::vector<PlyElement> elements;
  size_t data_offset = 0;  // the first byte after the 'end_header' line
  int data_line = 0;       // the line the data starts on (ASCII)
  // Where the geometry is: indices into `elements` and their `properties`; -1 if absent.
  int vertex_element = -1, face_element = -1;
  int xyz[3] = {-1, -1, -1};
  int face_indices = -1;  // the 'vertex_indices' (or 'vertex_index') list
  long long vertices = 0, faces = 0;
};

// Refuses with "<source>: could not parse it as PLY: line N: ..." a header it cannot use: one
// without a vertex element with x, y and z, or with a face element without an index list.
PlyHeader parse_ply_header(std::string_view bytes, const std::string& source);

}  // namespace paver::mesh_detail
