#include "mesh/ply_reader.h"

#include "mesh/mesh_messages.h"
#include "mesh/ply_header.h"
#include "mesh/reader_support.h"

#include <algorithm>
#include <cstdint>

namespace paver {
namespace {

using namespace mesh_detail;

constexpr int kIndices = 3;  // role of the face index list; 0, 1, 2 are x, y, z; -1 anything else

int role_of(const PlyHeader& header, int element, int property) {
  if (element == header.vertex_element)
    for (int axis = 0; axis < 3; ++axis)
      if (header.xyz[axis] == property) return axis;
  if (element == header.face_element && header.face_indices == property) return kIndices;
  return -1;
}

std::string record_name(const PlyElement& element, long long record) {
  return element.name + " " + std::to_string(record) + " (counting from 0)";
}

std::string index_out_of_range(long long face, long long index, long long vertices) {
  return "face " + std::to_string(face) + " (counting from 0) refers to vertex " + std::to_string(index) +
         ", but the header declares " + count_of(vertices, "vertex", "vertices") + " (PLY indices count from 0)";
}

// Values and records are separated by any whitespace; a value takes at least 2 bytes of text.
void read_ascii(std::string_view bytes, const PlyHeader& header, const std::string& source,
                CoordinateReader& coordinates, PolygonSoup& soup) {
  TokenReader reader(bytes.substr(header.data_offset), header.data_line);
  const size_t text_size = bytes.size() - header.data_offset;
  std::string_view token;
  for (int e = 0; e < int(header.elements.size()); ++e) {
    const PlyElement& element = header.elements[size_t(e)];
    const size_t most = text_size / (2 * std::max<size_t>(1, element.properties.size()));
    if (e == header.vertex_element) soup.positions.reserve(std::min(size_t(element.count), most));
    if (e == header.face_element) soup.polygons.reserve(std::min(size_t(element.count), most));
    for (long long record = 0; record < element.count; ++record) {
      glm::dvec3 p(0.0);
      for (int i = 0; i < int(element.properties.size()); ++i) {
        const PlyProperty& property = element.properties[size_t(i)];
        const int role = role_of(header, e, i);
        auto next = [&] {
          if (!reader.next(token))
            fail(source, "the PLY data ends early, in " + element.name + " " + std::to_string(record) +
                             " (counting from 0) of the " + std::to_string(element.count) +
                             " the header declares (truncated file?)");
        };
        long long length = 1;
        if (property.list) {
          next();
          if (!parse_integer(token, length) || length < 0)
            fail(source, at_line(reader.line()) + "expected the length of the list '" + property.name + "' of " +
                             element.name + " " + std::to_string(record) + ", found " +
                             quoted(token));
        }
        std::vector<int>* polygon = role == kIndices ? &soup.polygons.emplace_back() : nullptr;
        const bool integer = ply_type_is_integer(property.type);
        for (long long k = 0; k < length; ++k) {
          next();
          double value = 0.0;
          long long index = 0;
          if (!(integer ? parse_integer(token, index) : parse_double(token, value)))
            fail(source, at_line(reader.line()) + quoted(token) + " is not " +
                             (integer ? "an integer" : "a number") + " (property '" + property.name + "' of " +
                             element.name + " " + std::to_string(record) + ")");
          if (role == kIndices) {
            if (index < 0 || index >= header.vertices)
              fail(source, at_line(reader.line()) + index_out_of_range(record, index, header.vertices));
            polygon->push_back(int(index));
          } else if (role >= 0) {
            p[role] = coordinates.text(token, reader.line(), record);
          }
        }
      }
      if (e == header.vertex_element) soup.positions.push_back(p);
    }
  }
}

long long load_integer(std::string_view bytes, size_t at, PlyType type, bool big_endian) {
  const std::uint64_t raw = load_unsigned(bytes, at, ply_type_size(type), big_endian);
  switch (type) {
    case PlyType::Int8: return static_cast<std::int8_t>(raw);
    case PlyType::Int16: return static_cast<std::int16_t>(raw);
    case PlyType::Int32: return static_cast<std::int32_t>(raw);
    default: return static_cast<long long>(raw);  // unsigned types (the header allows no others)
  }
}

double load_value(std::string_view bytes, size_t at, PlyType type, bool big_endian) {
  if (type == PlyType::Float32) return load_float(bytes, at, big_endian);
  if (type == PlyType::Float64) return load_double(bytes, at, big_endian);
  return double(load_integer(bytes, at, type, big_endian));
}

void read_binary(std::string_view bytes, const PlyHeader& header, const std::string& source,
                 CoordinateReader& coordinates, PolygonSoup& soup) {
  const bool big_endian = header.format == PlyHeader::Format::BinaryBigEndian;
  const std::uint64_t size = bytes.size();
  const std::string mismatch = "could not parse it as PLY: binary PLY size mismatch: ";

  // Before allocating anything: the fewest bytes the declared elements take (empty lists).
  std::uint64_t needed = 0;
  std::string declared;
  for (const PlyElement& element : header.elements) {
    std::uint64_t record = 0;
    for (const PlyProperty& property : element.properties)
      record += ply_type_size(property.list ? property.count_type : property.type);
    needed += record * std::uint64_t(element.count);
    declared += (declared.empty() ? "" : ", ") + std::to_string(element.count) + " " + element.name;
  }
  if (needed > size - header.data_offset)
    fail(source, mismatch + "the header declares " + declared + ", which take at least " + std::to_string(needed) +
                     " bytes, but only " + std::to_string(size - header.data_offset) +
                     " follow the header (from byte offset " + std::to_string(header.data_offset) +
                     "); truncated file?");
  // Now bounded by the file length: a vertex takes 3 bytes or more, a face at least 1.
  soup.positions.reserve(size_t(header.vertices));
  soup.polygons.reserve(size_t(header.faces));

  std::uint64_t at = header.data_offset;
  for (int e = 0; e < int(header.elements.size()); ++e) {
    const PlyElement& element = header.elements[size_t(e)];
    auto ends_inside = [&](long long record, const std::string& detail) {
      fail(source, mismatch + "the file ends (at byte offset " + std::to_string(size) + ") inside " +
                       record_name(element, record) + " of the " + std::to_string(element.count) +
                       " the header declares" + detail + "; truncated file?");
    };
    for (long long record = 0; record < element.count; ++record) {
      glm::dvec3 p(0.0);
      for (int i = 0; i < int(element.properties.size()); ++i) {
        const PlyProperty& property = element.properties[size_t(i)];
        const int role = role_of(header, e, i);
        std::uint64_t length = 1;
        if (property.list) {
          const size_t count_size = ply_type_size(property.count_type);
          if (size - at < count_size) ends_inside(record, "");
          const long long signed_length = load_integer(bytes, at, property.count_type, big_endian);
          if (signed_length < 0)
            fail(source, at_byte(at) + "the list '" + property.name + "' of " + record_name(element, record) +
                             " has the negative length " + std::to_string(signed_length));
          length = std::uint64_t(signed_length);
          at += count_size;
        }
        const size_t item_size = ply_type_size(property.type);
        if ((size - at) / item_size < length)
          ends_inside(record, property.list ? ", whose list '" + property.name + "' (from byte offset " +
                                                  std::to_string(at) + ") says it has " + std::to_string(length) +
                                                  " items"
                                            : "");
        if (role == kIndices) {
          std::vector<int>& polygon = soup.polygons.emplace_back();
          polygon.reserve(length);
          for (std::uint64_t k = 0; k < length; ++k, at += item_size) {
            const long long index = load_integer(bytes, at, property.type, big_endian);
            if (index < 0 || index >= header.vertices)
              fail(source, at_byte(at) + index_out_of_range(record, index, header.vertices));
            polygon.push_back(int(index));
          }
        } else if (role >= 0) {
          p[role] = coordinates.binary(load_value(bytes, at, property.type, big_endian), at, record);
          at += item_size;
        } else {
          at += item_size * length;
        }
      }
      if (e == header.vertex_element) soup.positions.push_back(p);
    }
  }
}

}  // namespace

PolygonSoup read_ply(std::string_view bytes, const std::string& source) {
  const PlyHeader header = parse_ply_header(bytes, source);
  if (header.faces == 0)
    fail(source, "contains no faces (the PLY header declares " + count_of(header.vertices, "vertex", "vertices") +
                     " and no faces); Paver needs a surface, not a point cloud: export the faces too");
  PolygonSoup soup;
  CoordinateReader coordinates(source, "vertex", "vertices", 0);
  if (header.format == PlyHeader::Format::Ascii) read_ascii(bytes, header, source, coordinates, soup);
  else read_binary(bytes, header, source, coordinates, soup);
  coordinates.finish();
  return soup;
}

}  // namespace paver
