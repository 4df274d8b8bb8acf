#include "mesh/ply_header.h"

#include "mesh/mesh_messages.h"
#include "mesh/reader_support.h"

#include <algorithm>
#include <climits>
#include <optional>
#include <tuple>

namespace paver::mesh_detail {
namespace {

std::optional<PlyType> ply_type(std::string_view name) {
  if (name == "char" || name == "int8") return PlyType::Int8;
  if (name == "uchar" || name == "uint8") return PlyType::UInt8;
  if (name == "short" || name == "int16") return PlyType::Int16;
  if (name == "ushort" || name == "uint16") return PlyType::UInt16;
  if (name == "int" || name == "int32") return PlyType::Int32;
  if (name == "uint" || name == "uint32") return PlyType::UInt32;
  if (name == "float" || name == "float32") return PlyType::Float32;
  if (name == "double" || name == "float64") return PlyType::Float64;
  return std::nullopt;
}

bool is_index_list_name(std::string_view name) { return name == "vertex_indices" || name == "vertex_index"; }

}  // namespace

size_t ply_type_size(PlyType type) {
  switch (type) {
    case PlyType::Int8:
    case PlyType::UInt8: return 1;
    case PlyType::Int16:
    case PlyType::UInt16: return 2;
    case PlyType::Int32:
    case PlyType::UInt32:
    case PlyType::Float32: return 4;
    case PlyType::Float64: return 8;
  }
  return 0;
}

bool ply_type_is_integer(PlyType type) { return type != PlyType::Float32 && type != PlyType::Float64; }

PlyHeader parse_ply_header(std::string_view bytes, const std::string& source) {
  PlyHeader header;
  LineReader reader(bytes);
  std::string_view line;
  std::vector<std::string_view> tokens;
  const std::string cannot = "could not parse it as PLY: ";
  if (!reader.next(line) || (line != "ply" && line != "PLY"))
    fail(source, cannot + "it does not start with the 'ply' magic line");
  auto bad = [&](const std::string& what) { fail(source, cannot + at_line(reader.number()) + what); };
  bool have_format = false;
  while (reader.next(line)) {
    split_tokens(line, tokens);
    if (tokens.empty()) continue;
    const std::string_view keyword = tokens[0];
    if (!have_format && keyword != "format") bad("expected the 'format' line right after 'ply'");
    if (keyword == "comment" || keyword == "obj_info") continue;
    if (keyword == "end_header") {
      if (header.vertex_element < 0 || std::count(header.xyz, header.xyz + 3, -1) > 0)
        bad("the header declares no vertex element with x, y and z properties");
      if (header.face_element >= 0 && header.face_indices < 0)
        bad("the face element has no 'vertex_indices' list");
      header.data_offset = std::min(reader.offset(), bytes.size());
      header.data_line = reader.number() + 1;
      return header;
    }
    if (keyword == "format") {
      double version = 0.0;
      if (have_format || tokens.size() != 3 ||
          (tokens[1] != "ascii" && tokens[1] != "binary_little_endian" && tokens[1] != "binary_big_endian") ||
          !parse_double(tokens[2], version) || version != 1.0)
        bad("expected 'format ascii|binary_little_endian|binary_big_endian 1.0'");
      have_format = true;
      header.format = tokens[1] == "ascii"                  ? PlyHeader::Format::Ascii
                      : tokens[1] == "binary_little_endian" ? PlyHeader::Format::BinaryLittleEndian
                                                            : PlyHeader::Format::BinaryBigEndian;
    } else if (keyword == "element") {
      PlyElement element;
      if (tokens.size() != 3 || !parse_integer(tokens[2], element.count))
        bad("expected 'element <name> <count>'");
      // A count past what a mesh file can hold said "expected 'element <name> <count>'".
      if (element.count < 0 || element.count > INT_MAX)
        bad("the count " + std::string(tokens[2]) + " of '" + std::string(tokens[1]) + "' is " +
            (element.count < 0 ? "negative" : "beyond what Paver reads (" + std::to_string(INT_MAX) + ")"));
      element.name = std::string(tokens[1]);
      const int index = int(header.elements.size());
      for (auto [name, slot, count] : {std::tuple("vertex", &header.vertex_element, &header.vertices),
                                       std::tuple("face", &header.face_element, &header.faces)}) {
        if (element.name != name) continue;
        if (*slot >= 0) bad("a second '" + element.name + "' element");
        *slot = index;
        *count = element.count;
      }
      header.elements.push_back(std::move(element));
    } else if (keyword == "property") {
      if (header.elements.empty()) bad("a property before any element");
      PlyElement& element = header.elements.back();
      const int element_index = int(header.elements.size()) - 1;
      PlyProperty property;
      if (tokens.size() == 5 && tokens[1] == "list") {
        const auto count_type = ply_type(tokens[2]), type = ply_type(tokens[3]);
        if (!count_type || !type) bad("unknown list type");
        if (!ply_type_is_integer(*count_type))
          bad("a list length must have an integer type, not " + quoted(tokens[2]));
        property.list = true;
        property.count_type = *count_type;
        property.type = *type;
        property.name = std::string(tokens[4]);
      } else if (tokens.size() == 3 && tokens[1] != "list") {
        const auto type = ply_type(tokens[1]);
        if (!type) bad("unknown property type " + quoted(tokens[1]));
        property.type = *type;
        property.name = std::string(tokens[2]);
      } else {
        bad("expected 'property <type> <name>' or 'property list <count type> <item type> <name>'");
      }
      const int property_index = int(element.properties.size());
      if (element_index == header.vertex_element && !property.list) {
        for (int axis = 0; axis < 3; ++axis) {
          if (property.name != std::string(1, char('x' + axis))) continue;
          if (header.xyz[axis] >= 0) bad("the vertex element declares '" + property.name + "' twice");
          header.xyz[axis] = property_index;
        }
      }
      if (element_index == header.face_element && property.list && is_index_list_name(property.name) &&
          header.face_indices < 0) {
        if (!ply_type_is_integer(property.type))
          bad("the face list '" + property.name + "' must hold integers, not " + quoted(tokens[3]));
        header.face_indices = property_index;
      }
      element.properties.push_back(std::move(property));
    } else {
      bad(quoted(keyword) + " is not a PLY header keyword");
    }
  }
  bad("the header has no 'end_header' line");
  return header;  // not reached
}

}  // namespace paver::mesh_detail
