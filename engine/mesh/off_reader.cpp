#include "mesh/off_reader.h"

#include "mesh/mesh_messages.h"
#include "mesh/reader_support.h"

#include <algorithm>
#include <climits>
#include <cstdint>

namespace paver {
namespace {

using namespace mesh_detail;

// What the header keyword [ST][C][N][4][n]OFF says is stored per vertex besides x y z.
struct OffLayout {
  bool texcoords = false, colours = false, normals = false;
};

enum class OffKeyword { Ok, HigherDimension, NotOff };

OffKeyword parse_off_keyword(std::string_view keyword, OffLayout& layout) {
  layout.texcoords = keyword.substr(0, 2) == "ST";
  if (layout.texcoords) keyword.remove_prefix(2);
  layout.colours = !keyword.empty() && keyword.front() == 'C';
  if (layout.colours) keyword.remove_prefix(1);
  layout.normals = !keyword.empty() && keyword.front() == 'N';
  if (layout.normals) keyword.remove_prefix(1);
  bool higher = false;
  while (!keyword.empty() && (keyword.front() == '4' || keyword.front() == 'n')) {
    higher = true;
    keyword.remove_prefix(1);
  }
  if (keyword != "OFF") return OffKeyword::NotOff;
  return higher ? OffKeyword::HigherDimension : OffKeyword::Ok;
}

std::string vertex_count_hint(long long vertex_count) {
  return "the file has " + count_of(vertex_count, "vertex", "vertices") + " and OFF indices count from 0";
}

// `reader` is past line 1, the keyword alone; then the counts, then exactly that many vertex and face lines.
PolygonSoup read_off_text(LineReader reader, const OffLayout& layout, const std::string& source) {
  // The non-empty lines after the header; a '#' comment is refused, as it always has been.
  struct DataLine {
    std::string_view text;
    int number;
  };
  std::vector<DataLine> data;
  std::string_view line;
  while (reader.next(line)) {
    if (line.empty()) continue;
    if (line.find('#') != std::string_view::npos)
      fail(source, at_line(reader.number()) + "'#' comments are not supported in OFF files; delete the comment");
    data.push_back({line, reader.number()});
  }

  if (data.empty())
    fail(source, "the file ends after the OFF header; it contains no faces (the counts line is missing)");
  std::vector<std::string_view> tokens;
  split_tokens(data[0].text, tokens);
  const int counts_line = data[0].number;
  long long counts[3] = {0, 0, 0};
  bool counts_ok = tokens.size() == 3;
  for (size_t i = 0; i < 3 && counts_ok; ++i)
    counts_ok = parse_integer(tokens[i], counts[i]) && counts[i] >= 0 && counts[i] <= INT_MAX;
  if (!counts_ok)
    fail(source, at_line(counts_line) +
                     "expected the counts '<vertices> <faces> <edges>' after the OFF header, found " +
                     quoted(data[0].text));
  const long long vertex_count = counts[0], face_count = counts[1];
  const std::string declared = "the counts on line " + std::to_string(counts_line) + " declare " +
                               count_of(vertex_count, "vertex", "vertices") + " and " +
                               count_of(face_count, "face", "faces");
  if (face_count == 0) fail(source, "contains no faces (" + declared + ")");
  // Checked up front: a mismatch otherwise shows up as a puzzling error in some later line.
  if (static_cast<long long>(data.size()) - 1 != vertex_count + face_count)
    fail(source, declared + " (" + std::to_string(vertex_count + face_count) + " lines), but " +
                     std::to_string(data.size() - 1) + " non-empty lines follow; fix the counts or the file");
  const std::string counts_hint = "; do the counts on line " + std::to_string(counts_line) + " match the file?";

  PolygonSoup soup;
  soup.positions.reserve(size_t(vertex_count));
  soup.polygons.reserve(size_t(face_count));
  CoordinateReader coordinates(source, "vertex", "vertices", 0);
  // Normals are checked as numbers; colours and texture coordinates may follow, and are ignored.
  const size_t numbers_per_vertex = layout.normals ? 6 : 3;
  for (long long v = 0; v < vertex_count; ++v) {
    const DataLine& vertex = data[size_t(1 + v)];
    split_tokens(vertex.text, tokens);
    if (tokens.size() < numbers_per_vertex)
      fail(source, at_line(vertex.number) + "a vertex line needs " + std::to_string(numbers_per_vertex) +
                       " numbers but has " + std::to_string(tokens.size()) + counts_hint);
    glm::dvec3 p;
    for (size_t i = 0; i < numbers_per_vertex; ++i) {
      double value = 0.0;
      if (!parse_double(tokens[i], value))
        fail(source, at_line(vertex.number) + quoted(tokens[i]) +
                         " is not a number; vertex coordinates must be numbers");
      if (i < 3) p[int(i)] = coordinates.text(tokens[i], vertex.number, v);
    }
    soup.positions.push_back(p);
  }
  for (long long f = 0; f < face_count; ++f) {
    const DataLine& face = data[size_t(1 + vertex_count + f)];
    split_tokens(face.text, tokens);
    long long corners = 0;
    if (!parse_integer(tokens[0], corners))
      fail(source, at_line(face.number) + "a face line must start with its vertex count, found " +
                       quoted(tokens[0]) + counts_hint);
    if (corners < 3)
      fail(source, at_line(face.number) + "a face needs at least 3 vertices but this one has " +
                       std::to_string(corners) + counts_hint);
    if (tokens.size() < size_t(corners) + 1)
      fail(source, at_line(face.number) + "the face says it has " + std::to_string(corners) + " vertices but lists " +
                       std::to_string(tokens.size() - 1) + counts_hint);
    if (tokens.size() > size_t(corners) + 1 && !layout.colours)
      fail(source, at_line(face.number) + "the face has values after its " + std::to_string(corners) +
                       " vertex indices; remove them (face colours need a 'COFF' header)");
    std::vector<int>& polygon = soup.polygons.emplace_back();
    polygon.reserve(size_t(corners));
    for (long long i = 1; i <= corners; ++i) {
      long long index = 0;
      if (!parse_integer(tokens[size_t(i)], index))
        fail(source, at_line(face.number) + quoted(tokens[size_t(i)]) +
                         " is not a vertex index");
      if (index < 0 || index >= vertex_count)
        fail(source, at_line(face.number) + "face vertex index " + std::to_string(index) + " is out of range: " +
                         vertex_count_hint(vertex_count));
      polygon.push_back(int(index));
    }
  }
  coordinates.finish();
  return soup;
}

// After the header line: 4-byte counts (vertices, faces, edges), then per vertex x y z as floats
// [normal: 3 floats] [colour: 3 four-byte integers] [texture coordinates: 2 floats], then per face
// its size and indices as 4-byte integers, in `big_endian` order or little-endian. Face colours
// are not read.
std::uint64_t binary_vertex_size(const OffLayout& layout) {
  return 12 + (layout.normals ? 12 : 0) + (layout.colours ? 12 : 0) + (layout.texcoords ? 8 : 0);
}

// The smallest body these counts allow (faces of 3 corners), checked before anything is allocated.
std::uint64_t least_binary_bytes(std::uint64_t vertices, std::uint64_t faces, const OffLayout& layout) {
  return vertices * binary_vertex_size(layout) + faces * 16;
}

// Whether the counts read in this byte order leave room for their vertices and faces in the file.
bool binary_counts_fit(std::string_view bytes, const OffLayout& layout, size_t start, bool big_endian) {
  if (bytes.size() < start + 12) return false;
  const std::uint64_t vertices = load_unsigned(bytes, start, 4, big_endian);
  const std::uint64_t faces = load_unsigned(bytes, start + 4, 4, big_endian);
  return faces > 0 && least_binary_bytes(vertices, faces, layout) <= bytes.size() - start - 12;
}

PolygonSoup read_off_binary(std::string_view bytes, const OffLayout& layout, size_t start, bool big_endian,
                            const std::string& source) {
  const std::uint64_t size = bytes.size();
  if (size < start + 12)
    fail(source, at_byte(start) + "the binary OFF file ends before its counts (vertices, faces, edges: three "
                                  "4-byte integers); truncated file?");
  const std::uint64_t vertex_count = load_unsigned(bytes, start, 4, big_endian);
  const std::uint64_t face_count = load_unsigned(bytes, start + 4, 4, big_endian);
  const std::uint64_t vertex_size = binary_vertex_size(layout);
  const std::uint64_t base = start + 12;
  const std::uint64_t needed = least_binary_bytes(vertex_count, face_count, layout);
  const std::string declared =
      count_of(static_cast<long long>(vertex_count), "vertex", "vertices") + " and " +
      count_of(static_cast<long long>(face_count), "face", "faces");
  if (needed > size - base)
    fail(source, at_byte(start) + "the counts declare " + declared + ", which take at least " +
                     std::to_string(needed) + " bytes, but only " + std::to_string(size - base) +
                     " follow them; the file is truncated or the counts are wrong");
  if (face_count == 0) fail(source, "contains no faces (the counts at byte offset " + std::to_string(start) +
                                        " declare " + declared + ")");

  PolygonSoup soup;
  soup.positions.reserve(vertex_count);
  soup.polygons.reserve(face_count);
  CoordinateReader coordinates(source, "vertex", "vertices", 0);
  for (std::uint64_t v = 0; v < vertex_count; ++v) {
    const std::uint64_t at = base + v * vertex_size;
    glm::dvec3 p;
    for (int i = 0; i < 3; ++i)
      p[i] = coordinates.binary(load_float(bytes, at + 4 * i, big_endian), at + 4 * i, static_cast<long long>(v));
    soup.positions.push_back(p);
  }
  std::uint64_t at = base + vertex_count * vertex_size;
  const std::string counts_hint = "; do the counts at byte offset " + std::to_string(start) + " match the file?";
  for (std::uint64_t f = 0; f < face_count; ++f) {
    const auto face = [f] { return "face " + std::to_string(f) + " (counting from 0)"; };
    if (size - at < 4)
      fail(source, at_byte(at) + "the file ends before " + face() + "; the counts declare " + declared +
                       " (truncated file?)");
    const std::uint64_t corners = load_unsigned(bytes, at, 4, big_endian);
    if (corners < 3)
      fail(source, at_byte(at) + face() + " has " + std::to_string(corners) +
                       " vertices; a face needs at least 3" + counts_hint);
    if ((size - at - 4) / 4 < corners)
      fail(source, at_byte(at) + face() + " says it has " + std::to_string(corners) + " vertices, but the file ends " +
                       std::to_string(size - at - 4) + " bytes later" + counts_hint);
    at += 4;
    std::vector<int>& polygon = soup.polygons.emplace_back();
    polygon.reserve(corners);
    for (std::uint64_t i = 0; i < corners; ++i, at += 4) {
      const std::uint64_t index = load_unsigned(bytes, at, 4, big_endian);
      if (index >= vertex_count)
        fail(source, at_byte(at) + face() + ": vertex index " + std::to_string(index) + " is out of range: " +
                         vertex_count_hint(static_cast<long long>(vertex_count)));
      polygon.push_back(int(index));
    }
  }
  if (at != size)
    fail(source, at_byte(at) + std::to_string(size - at) + " bytes follow the last face; the counts declare " +
                     declared + " (binary OFF face colours are not supported)" + counts_hint);
  coordinates.finish();
  return soup;
}

}  // namespace

PolygonSoup read_off(std::string_view bytes, const std::string& source) {
  LineReader reader(bytes);
  std::string_view line;
  std::vector<std::string_view> tokens;
  reader.next(line);
  split_tokens(line, tokens);
  OffLayout layout;
  const OffKeyword keyword = tokens.empty() ? OffKeyword::NotOff : parse_off_keyword(tokens[0], layout);
  if (keyword == OffKeyword::NotOff)
    fail(source, "line 1: an OFF file must start with the header 'OFF' (found " + quoted(line) +
                     "); is it really an OFF file?");
  if (keyword == OffKeyword::HigherDimension)
    fail(source, "line 1: '" + std::string(tokens[0]) + "' (vertices of other than 3 dimensions) is not supported; "
                     "export a plain 3D OFF file");
  if (tokens.size() == 2 && tokens[1] == "BINARY") {
    // Geomview's binary OFF is big-endian, OpenMesh writes the host's order (little-endian on
    // every machine we run on): the order is the one whose counts fit the file; little-endian
    // when neither does, so that the message shows the counts as OpenMesh would read them.
    const size_t start = std::min(reader.offset(), bytes.size());
    const bool big_endian = !binary_counts_fit(bytes, layout, start, false) && binary_counts_fit(bytes, layout, start, true);
    return read_off_binary(bytes, layout, start, big_endian, source);
  }
  if (tokens.size() >= 2)
    fail(source, "line 1: the OFF keyword must be alone on the first line; move " +
                     quoted(trim(line.substr(size_t(tokens[1].data() - line.data())))) +
                     " to a line of its own");
  return read_off_text(reader, layout, source);
}

}  // namespace paver
