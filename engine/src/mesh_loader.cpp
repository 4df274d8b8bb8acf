// Surface loading in two halves: reading a file into a polygon soup (positions + index lists),
// and make_surface(), which checks and repairs the soup into the SurfaceMesh Paver paves.
//
// Reading: OpenMesh's readers fill a PolygonSoup importer, not a PolyMesh, because the PolyMesh
// importer silently duplicates vertices to "fix" non-manifold input (hiding the very problems we
// report) and prints to stderr. OpenMesh's text readers also skip lines they cannot parse without
// saying so (a bad 'v' line shifts every later index), so OBJ and OFF are pre-scanned first to
// name the line of a problem.
//
// Repairs, each reported in LoadedSurface::warnings: degenerate faces are dropped, polygons are
// triangulated, unreferenced vertices are dropped, faces are reoriented consistently.
// Several connected components: we KEEP THE LARGEST (by face count) and drop the others with a
// warning. Stray specks and leftover fragments are common in scans and exports, and refusing the
// whole file for them would be unhelpful; the warning says how much was dropped, so a user with
// two real pieces notices. Components are joined through shared vertices, so pieces touching at a
// single vertex stay one component and are refused as non-manifold there. The manifold,
// orientation and boundary checks look at the kept component only.
// Everything else (non-manifold, non-orientable, closed, several holes, handles) is an InputError
// that names the file, the place and the fix.
#include "paver/mesh_loader.h"

#include "paver/input_error.h"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/IO/importer/BaseImporter.hh>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cfloat>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <limits>
#include <mutex>
#include <numeric>
#include <sstream>
#include <string_view>
#include <system_error>
#include <utility>

namespace paver {
namespace {

[[noreturn]] void fail(const std::string& source, const std::string& what) {
  throw InputError(source + ": " + what);
}

std::string count_of(long long n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

std::string format_point(const glm::dvec3& p) {
  std::ostringstream out;
  out << '(' << p.x << ", " << p.y << ", " << p.z << ')';
  return out.str();
}

std::string lowercase(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = char(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// ---------------------------------------------------------------------------------------------
// Reading through OpenMesh

// Records what the readers report: positions and per-face vertex index lists, exactly as in the
// file (no merging, no validation; make_surface checks everything). Other attributes are ignored.
class PolygonSoup final : public OpenMesh::IO::BaseImporter {
public:
  std::vector<glm::dvec3> positions;
  std::vector<std::vector<int>> polygons;

  OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3f& p) override {
    return push_vertex(glm::dvec3(p[0], p[1], p[2]));
  }
  OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3d& p) override {
    return push_vertex(glm::dvec3(p[0], p[1], p[2]));
  }
  OpenMesh::VertexHandle add_vertex() override { return push_vertex(glm::dvec3(0.0)); }
  void set_point(OpenMesh::VertexHandle v, const OpenMesh::Vec3f& p) override {
    if (v.idx() >= 0 && size_t(v.idx()) < positions.size()) positions[v.idx()] = glm::dvec3(p[0], p[1], p[2]);
  }
  OpenMesh::FaceHandle add_face(const VHandles& vertices) override {
    std::vector<int>& polygon = polygons.emplace_back();
    polygon.reserve(vertices.size());
    for (const OpenMesh::VertexHandle& v : vertices) polygon.push_back(v.idx());
    return OpenMesh::FaceHandle(int(polygons.size()) - 1);
  }
  size_t n_vertices() const override { return positions.size(); }
  size_t n_faces() const override { return polygons.size(); }
  size_t n_edges() const override { return 0; }

  // Half-edge construction (used by the OM format only) and attributes: not needed.
  OpenMesh::HalfedgeHandle add_edge(OpenMesh::VertexHandle, OpenMesh::VertexHandle) override {
    return OpenMesh::HalfedgeHandle();
  }
  OpenMesh::FaceHandle add_face(OpenMesh::HalfedgeHandle) override { return OpenMesh::FaceHandle(); }
  void add_face_texcoords(OpenMesh::FaceHandle, OpenMesh::VertexHandle,
                          const std::vector<OpenMesh::Vec2f>&) override {}
  void add_face_texcoords(OpenMesh::FaceHandle, OpenMesh::VertexHandle,
                          const std::vector<OpenMesh::Vec3f>&) override {}
  void set_face_texindex(OpenMesh::FaceHandle, int) override {}
  void set_halfedge(OpenMesh::VertexHandle, OpenMesh::HalfedgeHandle) override {}
  void set_normal(OpenMesh::VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_normal(OpenMesh::VertexHandle, const OpenMesh::Vec3d&) override {}
  void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec4f&) override {}
  void set_texcoord(OpenMesh::VertexHandle, const OpenMesh::Vec2f&) override {}
  void set_status(OpenMesh::VertexHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_next(OpenMesh::HalfedgeHandle, OpenMesh::HalfedgeHandle) override {}
  void set_face(OpenMesh::HalfedgeHandle, OpenMesh::FaceHandle) override {}
  void request_face_texcoords2D() override {}
  void set_texcoord(OpenMesh::HalfedgeHandle, const OpenMesh::Vec2f&) override {}
  void set_texcoord(OpenMesh::VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_texcoord(OpenMesh::HalfedgeHandle, const OpenMesh::Vec3f&) override {}
  void set_status(OpenMesh::HalfedgeHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec3f&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec4f&) override {}
  void set_status(OpenMesh::EdgeHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_normal(OpenMesh::FaceHandle, const OpenMesh::Vec3f&) override {}
  void set_normal(OpenMesh::FaceHandle, const OpenMesh::Vec3d&) override {}
  void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec3f&) override {}
  void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec4f&) override {}
  void set_status(OpenMesh::FaceHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void add_texture_information(int, std::string) override {}

private:
  OpenMesh::VertexHandle push_vertex(const glm::dvec3& p) {
    positions.push_back(p);
    return OpenMesh::VertexHandle(int(positions.size()) - 1);
  }
};

// OpenMesh's reader modules are process-wide singletons with per-read member state, and they
// print diagnostics (e.g. a missing .mtl file) to its log streams. Reads are serialized, and the
// streams muted while one runs: our own errors say what went wrong, and we must not print.
class OpenMeshReadLock {
public:
  OpenMeshReadLock() : lock_(mutex()) {
    for (OpenMesh::mostream* stream : streams()) {
      enabled_.push_back(stream->is_enabled());
      stream->disable();
    }
  }
  ~OpenMeshReadLock() {
    for (size_t i = 0; i < streams().size(); ++i)
      if (enabled_[i]) streams()[i]->enable();
  }
  OpenMeshReadLock(const OpenMeshReadLock&) = delete;
  OpenMeshReadLock& operator=(const OpenMeshReadLock&) = delete;

private:
  static std::mutex& mutex() {
    static std::mutex m;
    return m;
  }
  static std::array<OpenMesh::mostream*, 3> streams() {
    return {&omerr(), &omout(), &omlog()};
  }
  std::lock_guard<std::mutex> lock_;
  std::vector<bool> enabled_;
};

// ---------------------------------------------------------------------------------------------
// Text pre-scans (OBJ, OFF)

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

void split_tokens(std::string_view line, std::vector<std::string_view>& tokens) {
  tokens.clear();
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_space(line[i])) ++i;
    const size_t start = i;
    while (i < line.size() && !is_space(line[i])) ++i;
    if (i > start) tokens.push_back(line.substr(start, i - start));
  }
}

// Walks a text one line at a time; line numbers count from 1.
class LineReader {
public:
  explicit LineReader(std::string_view text) : text_(text) {}
  bool next(std::string_view& line) {
    if (pos_ >= text_.size()) return false;
    const size_t end = std::min(text_.find('\n', pos_), text_.size());
    line = trim(text_.substr(pos_, end - pos_));
    pos_ = end + 1;
    ++number_;
    return true;
  }
  int number() const { return number_; }

private:
  std::string_view text_;
  size_t pos_ = 0;
  int number_ = 0;
};

// A whole token as a double; accepts a leading '+', "nan" and "inf" (reported later as
// non-finite), and maps overflow to infinity.
bool parse_double(std::string_view token, double& value) {
  if (!token.empty() && token.front() == '+') {
    token.remove_prefix(1);
    if (!token.empty() && token.front() == '-') return false;
  }
  if (token.empty()) return false;
  const char* end = token.data() + token.size();
  const auto result = std::from_chars(token.data(), end, value);
  if (result.ptr != end) return false;
  if (result.ec == std::errc::result_out_of_range) value = std::strtod(std::string(token).c_str(), nullptr);
  else if (result.ec != std::errc()) return false;
  return true;
}

bool parse_integer(std::string_view token, long long& value) {
  if (!token.empty() && token.front() == '+') {
    token.remove_prefix(1);
    if (!token.empty() && token.front() == '-') return false;
  }
  if (token.empty()) return false;
  const char* end = token.data() + token.size();
  const auto result = std::from_chars(token.data(), end, value);
  return result.ec == std::errc() && result.ptr == end;
}

std::string at_line(int line) { return "line " + std::to_string(line) + ": "; }

// Coordinates OpenMesh's text readers cannot take: they read single precision with operator>>,
// which rejects nan/inf and values beyond FLT_MAX and then skips or garbles the vertex. So these
// are caught here, where the line is known.
struct NonFinite {
  int count = 0;  // vertices with at least one non-finite coordinate
  int first_line = 0;
  long long first_vertex = 0;
  std::string first_token;

  // `vertex_counted` is per vertex, so a vertex with several bad coordinates counts once.
  void check(std::string_view token, double value, int line, long long vertex, bool& vertex_counted) {
    if (std::isfinite(value) || vertex_counted) return;
    vertex_counted = true;
    if (count++ > 0) return;
    first_line = line;
    first_vertex = vertex;
    first_token = std::string(token);
  }
};

void check_single_precision(const std::string& source, int line, std::string_view token, double value) {
  if (std::isfinite(value) && std::abs(value) > double(FLT_MAX))
    fail(source, at_line(line) + "coordinate " + std::string(token) +
                     " is too large: OpenMesh reads coordinates in single precision (at most about 3.4e38); "
                     "rescale the model");
}

struct TextScan {
  long long vertices = 0;
  long long faces = 0;          // faces OpenMesh will pass on
  int collapsed_faces = 0;      // OBJ faces with fewer than 3 distinct vertices; OpenMesh drops them
};

// Checks every 'v', 'vt' and 'f' line the way OpenMesh's OBJ reader will read it.
TextScan prescan_obj(std::string_view text, const std::string& source) {
  TextScan scan;
  long long& vertices = scan.vertices;
  long long& faces = scan.faces;
  NonFinite nonfinite;
  struct ForwardReference {
    int line;
    long long index;
  };
  std::vector<ForwardReference> forward;  // 1-based indices past the vertices seen so far
  std::vector<std::string_view> tokens;
  std::vector<long long> corners;

  LineReader reader(text);
  std::string_view line;
  while (reader.next(line)) {
    line = line.substr(0, line.find('#'));  // OpenMesh ignores what follows a '#' on 'v' and 'f' lines too
    if (line.empty()) continue;
    const int number = reader.number();
    split_tokens(line, tokens);
    const std::string_view keyword = tokens.front();
    if (keyword == "v") {
      if (tokens.size() < 4)
        fail(source, at_line(number) + "a 'v' line needs 3 coordinates (x y z) but has " +
                         std::to_string(tokens.size() - 1) + "; fix or delete the line");
      bool counted = false;
      for (size_t i = 1; i <= 3; ++i) {
        double value = 0.0;
        if (!parse_double(tokens[i], value))
          fail(source, at_line(number) + "'" + std::string(tokens[i]) +
                           "' is not a number; vertex coordinates must be numbers");
        check_single_precision(source, number, tokens[i], value);
        nonfinite.check(tokens[i], value, number, vertices + 1, counted);
      }
      ++vertices;
    } else if (keyword == "vt") {
      // OpenMesh gives up on the whole file at a texture coordinate it cannot read.
      double value = 0.0;
      if (tokens.size() < 3 || !parse_double(tokens[1], value) || !parse_double(tokens[2], value))
        fail(source, at_line(number) + "a 'vt' line needs 2 or 3 numbers (u v [w]); fix or delete the line");
    } else if (keyword == "f") {
      if (tokens.size() < 4)
        fail(source, at_line(number) + "a face needs at least 3 vertices but this one has " +
                         std::to_string(tokens.size() - 1));
      corners.clear();
      for (size_t i = 1; i < tokens.size(); ++i) {
        const std::string_view corner = tokens[i];
        const size_t slash = corner.find('/');
        const std::string_view vertex = corner.substr(0, slash);
        long long index = 0;
        if (vertex.empty())
          fail(source, at_line(number) + "face corner '" + std::string(corner) + "' has no vertex index");
        if (!parse_integer(vertex, index))
          fail(source, at_line(number) + "'" + std::string(corner) + "' is not a vertex index");
        if (slash != std::string_view::npos) {
          // Texture and normal indices are not used, but must be integers for OpenMesh to read on.
          std::string_view rest = corner.substr(slash + 1);
          while (true) {
            const size_t next = rest.find('/');
            long long ignored = 0;
            const std::string_view part = rest.substr(0, next);
            if (!part.empty() && !parse_integer(part, ignored))
              fail(source, at_line(number) + "'" + std::string(corner) + "' is not a valid face corner (v/vt/vn)");
            if (next == std::string_view::npos) break;
            rest = rest.substr(next + 1);
          }
        }
        if (index == 0)
          fail(source, at_line(number) + "vertex index 0 is invalid: OBJ indices start at 1");
        if (index < 0) {
          if (vertices + index < 0)
            fail(source, at_line(number) + "relative index " + std::to_string(index) +
                             " points before the first vertex: only " + count_of(vertices, "vertex is", "vertices are") +
                             " defined above this line");
          index = vertices + index + 1;
        } else if (index > vertices) {
          forward.push_back({number, index});
        }
        corners.push_back(index);
      }
      std::sort(corners.begin(), corners.end());
      const auto distinct = std::distance(corners.begin(), std::unique(corners.begin(), corners.end()));
      if (distinct < 3) ++scan.collapsed_faces;
      else ++faces;
    }
  }
  for (const ForwardReference& reference : forward)
    if (reference.index > vertices)
      fail(source, at_line(reference.line) + "the face refers to vertex " + std::to_string(reference.index) +
                       " but the file defines only " + count_of(vertices, "vertex", "vertices") +
                       " (OBJ indices count from 1)");
  if (nonfinite.count > 0)
    fail(source, at_line(nonfinite.first_line) + "vertex " + std::to_string(nonfinite.first_vertex) +
                     " (counting from 1) has a non-finite coordinate '" + nonfinite.first_token + "'; " +
                     count_of(nonfinite.count, "vertex has", "vertices have") +
                     " NaN or infinite coordinates: fix them in the modelling tool and export again");
  if (faces + scan.collapsed_faces == 0)
    fail(source, "contains no faces (" + count_of(vertices, "vertex", "vertices") +
                     ", no 'f' lines); Paver needs a surface, not a point cloud: export the faces too");
  return scan;
}

enum class OffKeyword { Ok, HigherDimension, NotOff };

// Parses the [ST][C][N][4][n]OFF header keyword.
OffKeyword parse_off_keyword(std::string_view keyword, bool& colors, bool& normals) {
  if (keyword.substr(0, 2) == "ST") keyword.remove_prefix(2);
  colors = !keyword.empty() && keyword.front() == 'C';
  if (colors) keyword.remove_prefix(1);
  normals = !keyword.empty() && keyword.front() == 'N';
  if (normals) keyword.remove_prefix(1);
  bool higher = false;
  while (!keyword.empty() && (keyword.front() == '4' || keyword.front() == 'n')) {
    higher = true;
    keyword.remove_prefix(1);
  }
  if (keyword != "OFF") return OffKeyword::NotOff;
  return higher ? OffKeyword::HigherDimension : OffKeyword::Ok;
}

// Checks an ASCII OFF file the way OpenMesh's OFF reader will read it: the keyword alone on line 1,
// then the counts, then exactly that many vertex and face lines. Binary OFF is left to OpenMesh.
TextScan prescan_off(std::string_view text, const std::string& source) {
  TextScan scan;
  LineReader reader(text);
  std::string_view line;
  std::vector<std::string_view> tokens;
  reader.next(line);
  split_tokens(line, tokens);
  bool colors = false, normals = false;
  const OffKeyword keyword = tokens.empty() ? OffKeyword::NotOff : parse_off_keyword(tokens[0], colors, normals);
  if (keyword == OffKeyword::NotOff)
    fail(source, "line 1: an OFF file must start with the header 'OFF' (found '" + std::string(line.substr(0, 40)) +
                     "'); is it really an OFF file?");
  if (keyword == OffKeyword::HigherDimension)
    fail(source, "line 1: '" + std::string(tokens[0]) + "' (vertices of other than 3 dimensions) is not supported; "
                     "export a plain 3D OFF file");
  if (tokens.size() >= 2 && tokens[1] == "BINARY") return scan;
  if (tokens.size() >= 2)
    fail(source, "line 1: OpenMesh's OFF reader needs the keyword alone on the first line; move '" +
                     std::string(trim(line.substr(tokens[1].data() - line.data()))) + "' to a line of its own");

  // The non-empty lines after the header. Blank lines are harmless to OpenMesh, '#' comments are not.
  struct DataLine {
    std::string_view text;
    int number;
  };
  std::vector<DataLine> data;
  while (reader.next(line)) {
    if (line.empty()) continue;
    if (line.find('#') != std::string_view::npos)
      fail(source, at_line(reader.number()) + "OpenMesh's OFF reader cannot skip '#' comments; delete the comment");
    data.push_back({line, reader.number()});
  }

  if (data.empty()) fail(source, "the file ends after the OFF header; it contains no faces (the counts line is missing)");
  split_tokens(data[0].text, tokens);
  const int counts_line = data[0].number;
  long long counts[3] = {0, 0, 0};
  bool counts_ok = tokens.size() == 3;
  for (size_t i = 0; i < 3 && counts_ok; ++i)
    counts_ok = parse_integer(tokens[i], counts[i]) && counts[i] >= 0 && counts[i] <= INT_MAX;
  if (!counts_ok)
    fail(source, at_line(counts_line) + "expected the counts '<vertices> <faces> <edges>' after the OFF header, found '" +
                     std::string(data[0].text.substr(0, 40)) + "'");
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

  NonFinite nonfinite;
  const size_t numbers_per_vertex = normals ? 6 : 3;
  for (long long v = 0; v < vertex_count; ++v) {
    const DataLine& vertex = data[size_t(1 + v)];
    split_tokens(vertex.text, tokens);
    if (tokens.size() < numbers_per_vertex)
      fail(source, at_line(vertex.number) + "a vertex line needs " + std::to_string(numbers_per_vertex) +
                       " numbers but has " + std::to_string(tokens.size()) + counts_hint);
    bool counted = false;
    for (size_t i = 0; i < numbers_per_vertex; ++i) {
      double value = 0.0;
      if (!parse_double(tokens[i], value))
        fail(source, at_line(vertex.number) + "'" + std::string(tokens[i]) +
                         "' is not a number; vertex coordinates must be numbers");
      if (i < 3) {
        check_single_precision(source, vertex.number, tokens[i], value);
        nonfinite.check(tokens[i], value, vertex.number, v, counted);
      }
    }
  }
  for (long long f = 0; f < face_count; ++f) {
    const DataLine& face = data[size_t(1 + vertex_count + f)];
    split_tokens(face.text, tokens);
    long long corners = 0;
    if (!parse_integer(tokens[0], corners))
      fail(source, at_line(face.number) + "a face line must start with its vertex count, found '" +
                       std::string(tokens[0]) + "'" + counts_hint);
    if (corners < 3)
      fail(source, at_line(face.number) + "a face needs at least 3 vertices but this one has " +
                       std::to_string(corners) + counts_hint);
    if (tokens.size() < size_t(corners) + 1)
      fail(source, at_line(face.number) + "the face says it has " + std::to_string(corners) + " vertices but lists " +
                       std::to_string(tokens.size() - 1) + counts_hint);
    if (tokens.size() > size_t(corners) + 1 && !colors)
      fail(source, at_line(face.number) + "the face has values after its " + std::to_string(corners) +
                       " vertex indices; remove them (face colours need a 'COFF' header)");
    for (long long i = 1; i <= corners; ++i) {
      long long index = 0;
      if (!parse_integer(tokens[size_t(i)], index))
        fail(source, at_line(face.number) + "'" + std::string(tokens[size_t(i)]) + "' is not a vertex index");
      if (index < 0 || index >= vertex_count)
        fail(source, at_line(face.number) + "face vertex index " + std::to_string(index) +
                         " is out of range: the file has " + count_of(vertex_count, "vertex", "vertices") +
                         " and OFF indices count from 0");
    }
  }
  if (nonfinite.count > 0)
    fail(source, at_line(nonfinite.first_line) + "vertex " + std::to_string(nonfinite.first_vertex) +
                     " (counting from 0) has a non-finite coordinate '" + nonfinite.first_token + "'; " +
                     count_of(nonfinite.count, "vertex has", "vertices have") +
                     " NaN or infinite coordinates: fix them in the modelling tool and export again");
  scan.vertices = vertex_count;
  scan.faces = face_count;
  return scan;
}

// ---------------------------------------------------------------------------------------------
// Binary formats: cheap explanations for when OpenMesh fails

std::uint32_t read_u32_le(std::string_view bytes, size_t offset) {
  std::uint32_t value = 0;
  for (int i = 3; i >= 0; --i) value = (value << 8) | static_cast<unsigned char>(bytes[offset + size_t(i)]);
  return value;
}

bool starts_with_solid(std::string_view bytes) {
  const std::string_view text = trim(bytes.substr(0, 80));
  return lowercase(text.substr(0, 5)) == "solid";
}

bool stl_is_binary(std::string_view bytes) {
  return bytes.size() >= 84 && bytes.size() == 84 + 50 * std::uint64_t(read_u32_le(bytes, 80));
}

// The number of triangles the file declares (binary) or contains (ASCII 'endfacet' count).
long long stl_facet_count(std::string_view bytes) {
  if (stl_is_binary(bytes)) return read_u32_le(bytes, 80);
  long long count = 0;
  for (size_t at = bytes.find("endfacet"); at != std::string_view::npos; at = bytes.find("endfacet", at + 8)) ++count;
  return count;
}

std::string diagnose_stl(std::string_view bytes) {
  if (stl_is_binary(bytes)) return "the binary STL data is corrupt";
  if (starts_with_solid(bytes)) {
    if (stl_facet_count(bytes) == 0)
      return "it starts like ASCII STL ('solid') but has no 'facet ... endfacet' blocks";
    return "the ASCII STL text is malformed";
  }
  if (bytes.size() < 84)
    return "it does not start with 'solid' (ASCII STL) and is too short (" + std::to_string(bytes.size()) +
           " bytes) for binary STL, which has an 84-byte header";
  const std::uint64_t triangles = read_u32_le(bytes, 80);
  return "binary STL size mismatch: the header declares " + std::to_string(triangles) + " triangles, which take " +
         std::to_string(84 + 50 * triangles) + " bytes, but the file has " + std::to_string(bytes.size()) +
         " bytes (truncated or not an STL file)";
}

struct PlyHeader {
  std::string error;  // why the header is unusable, with its line; empty if it is well-formed
  std::string format;
  size_t data_offset = 0;
  long long vertices = 0, faces = 0;
  size_t min_data_bytes = 0;  // binary: the least the declared elements can take
};

size_t ply_type_size(std::string_view type) {
  if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
  if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
  if (type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" || type == "float32")
    return 4;
  if (type == "double" || type == "float64") return 8;
  return 0;
}

// Reads the header strictly: OpenMesh's PLY reader crashes on some malformed headers (a property
// before any element), so it must only ever see well-formed ones.
PlyHeader parse_ply_header(std::string_view bytes) {
  PlyHeader header;
  LineReader reader(bytes);
  std::string_view line;
  std::vector<std::string_view> tokens;
  if (!reader.next(line) || line != "ply") {
    header.error = "it does not start with the 'ply' magic line";
    return header;
  }
  auto bad = [&](const std::string& what) {
    header.error = at_line(reader.number()) + what;
    return header;
  };
  long long element_count = -1;  // -1: no element yet
  std::string_view element;
  bool vertex_xyz[3] = {false, false, false};
  while (reader.next(line)) {
    split_tokens(line, tokens);
    if (tokens.empty()) continue;
    const std::string_view keyword = tokens[0];
    if (keyword == "comment" || keyword == "obj_info") continue;
    if (keyword == "end_header") {
      if (header.format.empty()) return bad("the header has no 'format' line");
      if (!(vertex_xyz[0] && vertex_xyz[1] && vertex_xyz[2]))
        return bad("the header declares no vertex element with x, y and z properties");
      const size_t end = bytes.find('\n', size_t(line.data() - bytes.data()));
      header.data_offset = end == std::string_view::npos ? bytes.size() : end + 1;
      return header;
    }
    if (keyword == "format") {
      if (tokens.size() != 3 || (tokens[1] != "ascii" && tokens[1] != "binary_little_endian" &&
                                 tokens[1] != "binary_big_endian"))
        return bad("expected 'format ascii|binary_little_endian|binary_big_endian 1.0'");
      header.format = std::string(tokens[1]);
    } else if (keyword == "element") {
      if (tokens.size() != 3 || !parse_integer(tokens[2], element_count) || element_count < 0 ||
          element_count > INT_MAX)
        return bad("expected 'element <name> <count>'");
      element = tokens[1];
      if (element == "vertex") header.vertices = element_count;
      if (element == "face") header.faces = element_count;
    } else if (keyword == "property") {
      if (element_count < 0) return bad("a property before any element");
      size_t record = 0;
      if (tokens.size() == 5 && tokens[1] == "list") {
        // A list holds at least its count; a face's vertex list at least 3 indices.
        const size_t count_size = ply_type_size(tokens[2]), item_size = ply_type_size(tokens[3]);
        if (count_size == 0 || item_size == 0) return bad("unknown list type");
        record = count_size + (element == "face" ? 3 * item_size : 0);
      } else if (tokens.size() == 3 && tokens[1] != "list") {
        record = ply_type_size(tokens[1]);
        if (record == 0) return bad("unknown property type '" + std::string(tokens[1]) + "'");
        constexpr std::string_view axes[3] = {"x", "y", "z"};
        if (element == "vertex")
          for (int axis = 0; axis < 3; ++axis)
            if (tokens[2] == axes[axis]) vertex_xyz[axis] = true;
      } else {
        return bad("expected 'property <type> <name>' or 'property list <count type> <item type> <name>'");
      }
      header.min_data_bytes += record * size_t(element_count);
    } else {
      return bad("'" + std::string(keyword.substr(0, 40)) + "' is not a PLY header keyword");
    }
  }
  header.error = "the header has no 'end_header' line";
  return header;
}

std::string diagnose_ply(std::string_view bytes) {
  const PlyHeader header = parse_ply_header(bytes);
  if (!header.error.empty()) return header.error;
  const size_t data = bytes.size() - header.data_offset;
  const std::string declared = "the header declares " + count_of(header.vertices, "vertex", "vertices") + " and " +
                               count_of(header.faces, "face", "faces");
  if (header.format == "ascii") return declared + "; the ASCII data does not match them (truncated file?)";
  if (data < header.min_data_bytes)
    return "binary PLY size mismatch: " + declared + ", which take at least " + std::to_string(header.min_data_bytes) +
           " bytes after the header, but only " + std::to_string(data) + " bytes follow (truncated file?)";
  return declared + "; the binary data does not match them";
}

// ---------------------------------------------------------------------------------------------
// Checks and repairs

class DisjointSets {
public:
  explicit DisjointSets(size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
  int find(int x) {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];
      x = parent_[x];
    }
    return x;
  }
  void unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

private:
  std::vector<int> parent_;
};

double triangle_area(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  return 0.5 * glm::length(glm::cross(b - a, c - a));
}

double cross2(const glm::dvec2& a, const glm::dvec2& b) { return a.x * b.y - a.y * b.x; }

bool has_repeated_vertex(const std::vector<int>& polygon) {
  if (polygon.size() <= 8) {
    for (size_t i = 0; i < polygon.size(); ++i)
      for (size_t j = i + 1; j < polygon.size(); ++j)
        if (polygon[i] == polygon[j]) return true;
    return false;
  }
  std::vector<int> sorted = polygon;
  std::sort(sorted.begin(), sorted.end());
  return std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end();
}

// Splits a polygon (3+ distinct vertices, non-zero Newell area) into triangles by ear clipping in
// its best-fit plane, keeping its orientation; falls back to a fan from the remaining vertices
// when no ear is left (self-intersecting polygons). Returns how many zero-area triangles it had
// to leave out.
int triangulate_polygon(const std::vector<glm::dvec3>& positions, const std::vector<int>& polygon,
                        const glm::dvec3& newell, double min_area, std::vector<glm::ivec3>& out) {
  const int k = int(polygon.size());
  const glm::dvec3 n = glm::normalize(newell);
  const glm::dvec3 helper = std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  const glm::dvec3 u = glm::normalize(glm::cross(helper, n));
  const glm::dvec3 v = glm::cross(n, u);  // (u, v, n) right-handed: the polygon runs counter-clockwise
  const glm::dvec3& origin = positions[polygon[0]];
  std::vector<glm::dvec2> q(k);
  for (int i = 0; i < k; ++i) {
    const glm::dvec3 d = positions[polygon[i]] - origin;
    q[i] = glm::dvec2(glm::dot(d, u), glm::dot(d, v));
  }
  std::vector<int> prev(k), next(k);
  for (int i = 0; i < k; ++i) {
    prev[i] = (i + k - 1) % k;
    next[i] = (i + 1) % k;
  }

  int dropped = 0;
  auto emit = [&](int a, int b, int c) {
    const glm::ivec3 t(polygon[a], polygon[b], polygon[c]);
    if (triangle_area(positions[t.x], positions[t.y], positions[t.z]) < min_area) ++dropped;
    else out.push_back(t);
  };
  // An ear: a convex corner (with more than the degenerate-area tolerance) whose triangle holds no
  // other remaining vertex, on its edges included.
  auto is_ear = [&](int a, int b, int c) {
    if (0.5 * cross2(q[b] - q[a], q[c] - q[a]) <= min_area) return false;
    for (int r = next[c]; r != a; r = next[r]) {
      if (cross2(q[b] - q[a], q[r] - q[a]) >= 0 && cross2(q[c] - q[b], q[r] - q[b]) >= 0 &&
          cross2(q[a] - q[c], q[r] - q[c]) >= 0)
        return false;
    }
    return true;
  };

  int remaining = k, current = 0, misses = 0;
  while (remaining > 3 && misses < remaining) {
    const int a = prev[current], c = next[current];
    if (is_ear(a, current, c)) {
      out.push_back(glm::ivec3(polygon[a], polygon[current], polygon[c]));
      next[a] = c;
      prev[c] = a;
      --remaining;
      misses = 0;
      current = c;
    } else {
      current = c;
      ++misses;
    }
  }
  for (int b = next[current]; next[b] != current; b = next[b]) emit(current, b, next[b]);
  return dropped;
}

struct Triangulation {
  std::vector<glm::ivec3> triangles;
  int degenerate = 0;
};

Triangulation triangulate(const std::vector<glm::dvec3>& positions, const std::vector<std::vector<int>>& polygons,
                          double min_area) {
  Triangulation result;
  result.triangles.reserve(polygons.size());
  for (const std::vector<int>& polygon : polygons) {
    if (polygon.size() < 3 || has_repeated_vertex(polygon)) {
      ++result.degenerate;
      continue;
    }
    if (polygon.size() == 3) {
      const glm::ivec3 t(polygon[0], polygon[1], polygon[2]);
      if (triangle_area(positions[t.x], positions[t.y], positions[t.z]) < min_area) ++result.degenerate;
      else result.triangles.push_back(t);
      continue;
    }
    // Newell's normal: twice the vector area; robust for non-planar and non-convex polygons.
    glm::dvec3 newell(0.0);
    const glm::dvec3& origin = positions[polygon[0]];
    for (size_t i = 0; i < polygon.size(); ++i)
      newell += glm::cross(positions[polygon[i]] - origin, positions[polygon[(i + 1) % polygon.size()]] - origin);
    if (0.5 * glm::length(newell) < min_area) {
      ++result.degenerate;
      continue;
    }
    result.degenerate += triangulate_polygon(positions, polygon, newell, min_area, result.triangles);
  }
  return result;
}

// One side of a triangle: corner c runs from t[c] to t[(c + 1) % 3].
struct Side {
  std::uint64_t key;  // the undirected edge: (min vertex << 32) | max vertex
  int triangle;
  int corner;
};

std::uint64_t edge_key(int a, int b) {
  return (std::uint64_t(std::uint32_t(std::min(a, b))) << 32) | std::uint32_t(std::max(a, b));
}

int corner_of(const glm::ivec3& t, int vertex) { return t.x == vertex ? 0 : t.y == vertex ? 1 : 2; }

std::string edge_between(int a, int b, const std::vector<glm::dvec3>& positions) {
  return "the edge between vertices " + std::to_string(a) + " and " + std::to_string(b) + " (counting from 0) at " +
         format_point(positions[a]) + " - " + format_point(positions[b]);
}

LoadedSurface check_and_repair(std::vector<glm::dvec3> positions, const std::vector<std::vector<int>>& polygons,
                               const std::string& source, int collapsed_faces) {
  LoadedSurface loaded;
  const long long vertex_count = static_cast<long long>(positions.size());

  if (polygons.empty() && collapsed_faces == 0)
    fail(source, "contains no faces (" + count_of(vertex_count, "vertex", "vertices") +
                     "); Paver needs a surface, not a point cloud: export the faces too");
  for (size_t f = 0; f < polygons.size(); ++f)
    for (int index : polygons[f])
      if (index < 0 || index >= vertex_count)
        fail(source, "face " + std::to_string(f) + " (counting from 0) refers to vertex " + std::to_string(index) +
                         " but there are only " + count_of(vertex_count, "vertex", "vertices") +
                         "; the file is corrupt: export it again");

  int nonfinite = 0, first_nonfinite = -1;
  for (size_t v = 0; v < positions.size(); ++v) {
    const glm::dvec3& p = positions[v];
    if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) continue;
    if (nonfinite++ == 0) first_nonfinite = int(v);
  }
  if (nonfinite > 0)
    fail(source, "vertex " + std::to_string(first_nonfinite) + " (counting from 0) has a non-finite coordinate " +
                     format_point(positions[first_nonfinite]) + "; " +
                     count_of(nonfinite, "vertex has", "vertices have") +
                     " NaN or infinite coordinates: fix them in the modelling tool and export again");

  // Degenerate faces, relative to the size of the referenced geometry.
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (const std::vector<int>& polygon : polygons)
    for (int index : polygon) {
      lo = glm::min(lo, positions[index]);
      hi = glm::max(hi, positions[index]);
    }
  const double diagonal = polygons.empty() ? 0.0 : glm::length(hi - lo);
  const double min_area = 1e-12 * diagonal * diagonal;
  Triangulation triangulation = triangulate(positions, polygons, min_area);
  std::vector<glm::ivec3>& all_triangles = triangulation.triangles;
  const int degenerate = triangulation.degenerate + collapsed_faces;
  loaded.dropped_degenerate_faces = degenerate;
  if (all_triangles.empty())
    fail(source, "contains no faces after dropping " + count_of(degenerate, "degenerate face", "degenerate faces") +
                     " (zero area or repeated vertices); check the export");
  if (degenerate > 0)
    loaded.warnings.push_back(source + ": dropped " + count_of(degenerate, "degenerate face", "degenerate faces") +
                              " (zero area or repeated vertices)");

  std::vector<char> referenced(positions.size(), 0);
  for (const glm::ivec3& t : all_triangles) referenced[t.x] = referenced[t.y] = referenced[t.z] = 1;
  const long long unreferenced = std::count(referenced.begin(), referenced.end(), 0);
  if (unreferenced > 0)
    loaded.warnings.push_back(source + ": dropped " +
                              count_of(unreferenced, "unreferenced vertex", "unreferenced vertices") +
                              " (not used by any face)");

  // Components through shared vertices; keep the largest (see the comment at the top).
  DisjointSets vertex_sets(positions.size());
  for (const glm::ivec3& t : all_triangles) {
    vertex_sets.unite(t.x, t.y);
    vertex_sets.unite(t.x, t.z);
  }
  std::vector<int> component_faces(positions.size(), 0);
  for (const glm::ivec3& t : all_triangles) ++component_faces[vertex_sets.find(t.x)];
  int components = 0, largest = -1;
  for (size_t root = 0; root < component_faces.size(); ++root) {
    if (component_faces[root] == 0) continue;
    ++components;
    if (largest < 0 || component_faces[root] > component_faces[largest]) largest = int(root);
  }
  std::vector<glm::ivec3> triangles;
  if (components > 1) {
    triangles.reserve(component_faces[largest]);
    for (const glm::ivec3& t : all_triangles)
      if (vertex_sets.find(t.x) == largest) triangles.push_back(t);
    const long long dropped = static_cast<long long>(all_triangles.size() - triangles.size());
    loaded.dropped_components = components - 1;
    loaded.warnings.push_back(source + ": the surface has " + std::to_string(components) +
                              " connected components; kept the largest (" +
                              count_of(long(triangles.size()), "face", "faces") + ") and dropped the other " +
                              std::to_string(components - 1) + " (" + count_of(dropped, "face", "faces") + ")");
  } else {
    triangles = std::move(all_triangles);
  }
  const std::string kept_note =
      components > 1 ? " (in its largest connected component, the one Paver keeps; the file has " +
                           std::to_string(components) + ")"
                     : "";
  const int face_count = int(triangles.size());

  // Edges: group the triangle sides by undirected edge.
  std::vector<Side> sides;
  sides.reserve(size_t(face_count) * 3);
  for (int f = 0; f < face_count; ++f)
    for (int c = 0; c < 3; ++c) sides.push_back({edge_key(triangles[f][c], triangles[f][(c + 1) % 3]), f, c});
  std::sort(sides.begin(), sides.end(), [](const Side& a, const Side& b) {
    return a.key != b.key ? a.key < b.key : a.triangle != b.triangle ? a.triangle < b.triangle : a.corner < b.corner;
  });
  std::vector<std::pair<size_t, size_t>> edges;  // [begin, end) ranges of `sides`
  edges.reserve(sides.size() / 2 + 1);
  for (size_t begin = 0; begin < sides.size();) {
    size_t end = begin + 1;
    while (end < sides.size() && sides[end].key == sides[begin].key) ++end;
    edges.emplace_back(begin, end);
    begin = end;
  }

  int nonmanifold_edges = 0;
  size_t example_edge = 0;
  for (size_t e = 0; e < edges.size(); ++e) {
    if (edges[e].second - edges[e].first <= 2) continue;
    if (nonmanifold_edges++ == 0) example_edge = e;
  }
  if (nonmanifold_edges > 0) {
    const Side& side = sides[edges[example_edge].first];
    const glm::ivec3& t = triangles[side.triangle];
    fail(source, "has " + count_of(nonmanifold_edges, "non-manifold edge", "non-manifold edges") +
                     " (shared by more than 2 faces), e.g. " +
                     edge_between(t[side.corner], t[(side.corner + 1) % 3], positions) + ", shared by " +
                     std::to_string(edges[example_edge].second - edges[example_edge].first) +
                     " faces; Paver needs a manifold surface: remove the extra (duplicated or fin) faces" + kept_note);
  }

  // Non-manifold vertices: corners around a vertex joined across shared edges form its fans.
  std::vector<int> neighbour(size_t(face_count) * 3, -1);  // across side c of face f
  std::vector<char> same_direction(size_t(face_count) * 3, 0);
  DisjointSets corner_sets(size_t(face_count) * 3);
  for (const auto& [begin, end] : edges) {
    if (end - begin != 2) continue;
    const Side& s = sides[begin];
    const Side& r = sides[begin + 1];
    const glm::ivec3& ts = triangles[s.triangle];
    const glm::ivec3& tr = triangles[r.triangle];
    const int a = ts[s.corner], b = ts[(s.corner + 1) % 3];
    corner_sets.unite(s.triangle * 3 + s.corner, r.triangle * 3 + corner_of(tr, a));
    corner_sets.unite(s.triangle * 3 + (s.corner + 1) % 3, r.triangle * 3 + corner_of(tr, b));
    const bool same = tr[r.corner] == a;
    neighbour[s.triangle * 3 + s.corner] = r.triangle;
    neighbour[r.triangle * 3 + r.corner] = s.triangle;
    same_direction[s.triangle * 3 + s.corner] = same_direction[r.triangle * 3 + r.corner] = same;
  }
  std::vector<int> fans(positions.size(), 0);
  for (int f = 0; f < face_count; ++f)
    for (int c = 0; c < 3; ++c)
      if (corner_sets.find(f * 3 + c) == f * 3 + c) ++fans[triangles[f][c]];
  int nonmanifold_vertices = 0, example_vertex = -1;
  for (size_t v = 0; v < fans.size(); ++v) {
    if (fans[v] <= 1) continue;
    if (nonmanifold_vertices++ == 0) example_vertex = int(v);
  }
  if (nonmanifold_vertices > 0)
    fail(source, "has " + count_of(nonmanifold_vertices, "non-manifold vertex", "non-manifold vertices") +
                     ", e.g. vertex " + std::to_string(example_vertex) + " (counting from 0) at " +
                     format_point(positions[example_vertex]) + ", where " + std::to_string(fans[example_vertex]) +
                     " separate fans of faces meet at a single point (like two cones touching at their tips, or a "
                     "bowtie); Paver needs a manifold surface: pull the pieces apart or split the vertex" +
                     kept_note);

  // Orientation: spread each face's orientation to its neighbours; keep the majority's.
  std::vector<signed char> flip(size_t(face_count), -1);
  std::vector<int> queue;
  queue.reserve(size_t(face_count));
  for (int seed = 0; seed < face_count; ++seed) {
    if (flip[seed] >= 0) continue;
    flip[seed] = 0;
    queue.clear();
    queue.push_back(seed);
    for (size_t head = 0; head < queue.size(); ++head) {
      const int f = queue[head];
      for (int c = 0; c < 3; ++c) {
        const int g = neighbour[f * 3 + c];
        if (g < 0) continue;
        // Neighbours must run their shared edge in opposite directions.
        const signed char wanted = static_cast<signed char>(flip[f] ^ same_direction[f * 3 + c]);
        if (flip[g] < 0) {
          flip[g] = wanted;
          queue.push_back(g);
        } else if (flip[g] != wanted) {
          fail(source, "is not orientable (like a Moebius strip): its faces cannot be oriented consistently, "
                       "as seen at " +
                           edge_between(triangles[f][c], triangles[f][(c + 1) % 3], positions) +
                           "; Paver needs a two-sided surface" + kept_note);
        }
      }
    }
  }
  long long flipped = std::count(flip.begin(), flip.end(), 1);
  const bool invert = 2 * flipped > face_count;
  if (invert) flipped = face_count - flipped;
  for (int f = 0; f < face_count; ++f)
    if ((flip[f] == 1) != invert) std::swap(triangles[f].y, triangles[f].z);
  if (flipped > 0)
    loaded.warnings.push_back(source + ": reoriented " + count_of(flipped, "face", "faces") +
                              " to match their neighbours");

  // Boundary loops, following the direction of the boundary sides.
  std::vector<int> boundary_next(positions.size(), -1);
  int boundary_edges = 0, first_boundary = -1;
  for (const auto& [begin, end] : edges) {
    if (end - begin != 1) continue;
    // Faces may have been flipped since `sides` was built: read the direction off the face.
    const glm::ivec3& t = triangles[sides[begin].triangle];
    int c = 0;
    while (edge_key(t[c], t[(c + 1) % 3]) != sides[begin].key) ++c;
    const int from = t[c], to = t[(c + 1) % 3];
    boundary_next[from] = to;
    ++boundary_edges;
    if (first_boundary < 0 || from < first_boundary) first_boundary = from;
  }
  if (boundary_edges == 0)
    fail(source, "is a closed surface (it has no boundary edges); Paver needs an open surface with one boundary "
                 "loop; cut it open first" +
                     kept_note);
  std::vector<char> on_loop(positions.size(), 0);
  std::vector<int> loop_sizes;
  std::vector<int> loop;
  for (int start = 0; start < int(positions.size()); ++start) {
    if (boundary_next[start] < 0 || on_loop[start]) continue;
    int size = 0;
    for (int v = start; v >= 0 && !on_loop[v]; v = boundary_next[v]) {
      on_loop[v] = 1;
      if (start == first_boundary) loop.push_back(v);
      ++size;
    }
    loop_sizes.push_back(size);
  }
  if (loop_sizes.size() > 1) {
    std::sort(loop_sizes.rbegin(), loop_sizes.rend());
    std::string sizes;
    for (size_t i = 0; i < loop_sizes.size() && i < 5; ++i)
      sizes += (i == 0 ? "" : ", ") + std::to_string(loop_sizes[i]);
    if (loop_sizes.size() > 5) sizes += ", ...";
    fail(source, "has " + std::to_string(loop_sizes.size()) + " boundary loops (holes) of " + sizes +
                     " edges; Paver needs exactly one: fill the holes or cut the surface so that its boundary is a "
                     "single loop" +
                     kept_note);
  }

  // One boundary loop on a connected orientable surface: a disk exactly when V - E + F = 1.
  std::vector<char> used(positions.size(), 0);
  for (const glm::ivec3& t : triangles) used[t.x] = used[t.y] = used[t.z] = 1;
  long long used_vertices = 0;
  std::vector<int> new_index(positions.size(), -1);
  for (size_t v = 0; v < positions.size(); ++v)
    if (used[v]) new_index[v] = int(used_vertices++);
  const long long euler = used_vertices - static_cast<long long>(edges.size()) + face_count;
  if (euler != 1) {
    const long long genus = (1 - euler) / 2;
    fail(source, "is not a topological disk: it has one boundary loop but " + count_of(genus, "handle", "handles") +
                     " (V - E + F = " + std::to_string(euler) +
                     ", a disk has 1); Paver needs a disk-like surface: cut through the handles or fill them" +
                     kept_note);
  }

  SurfaceMesh& mesh = loaded.mesh;
  mesh.positions.resize(size_t(used_vertices));
  for (size_t v = 0; v < positions.size(); ++v)
    if (new_index[v] >= 0) mesh.positions[new_index[v]] = positions[v];
  mesh.triangles.reserve(triangles.size());
  for (const glm::ivec3& t : triangles) mesh.triangles.emplace_back(new_index[t.x], new_index[t.y], new_index[t.z]);
  mesh.boundary_loop.reserve(loop.size());
  for (int v : loop) mesh.boundary_loop.push_back(new_index[v]);
  return loaded;
}

}  // namespace

LoadedSurface make_surface(std::vector<glm::dvec3> positions, const std::vector<std::vector<int>>& polygons,
                           const std::string& source) {
  return check_and_repair(std::move(positions), polygons, source, 0);
}

LoadedSurface load_surface(const std::filesystem::path& path) {
  const std::string source = path.string();
  const std::string extension = lowercase(path.extension().string());
  if (extension != ".obj" && extension != ".off" && extension != ".ply" && extension != ".stl")
    fail(source, (extension.empty() ? std::string("has no file extension")
                                    : "unsupported file type '" + path.extension().string() + "'") +
                     "; Paver reads surfaces in OBJ, OFF, PLY (ASCII or binary) and STL (ASCII or binary) format "
                     "(.obj, .off, .ply, .stl)");

  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  if (!std::filesystem::exists(status)) fail(source, "file not found; check the path");
  if (std::filesystem::is_directory(status)) fail(source, "is a directory, not a mesh file");
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(source, "cannot be opened for reading; check its permissions");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) fail(source, "could not be read (I/O error)");
  if (bytes.empty()) fail(source, "the file is empty (0 bytes), so it contains no faces; export the surface again");

  TextScan scan;
  if (extension == ".obj") scan = prescan_obj(bytes, source);
  if (extension == ".off") scan = prescan_off(bytes, source);
  if (extension == ".ply") {
    const PlyHeader header = parse_ply_header(bytes);
    if (!header.error.empty()) fail(source, "OpenMesh could not parse it as PLY: " + header.error);
    if (header.faces == 0)
      fail(source, "contains no faces (the PLY header declares " + count_of(header.vertices, "vertex", "vertices") +
                       " and no faces); Paver needs a surface, not a point cloud: export the faces too");
  }
  int collapsed_faces = scan.collapsed_faces;

  PolygonSoup soup;
  bool read = false;
  {
    const OpenMeshReadLock lock;
    OpenMesh::IO::Options options;  // positions and faces only
    read = OpenMesh::IO::IOManager().read(source, soup, options);
  }
  const std::string format = extension == ".obj" ? "OBJ" : extension == ".off" ? "OFF" : extension == ".ply" ? "PLY" : "STL";
  if (!read) {
    std::string what = "the file looked well-formed, so this is unexpected; try exporting it again";
    if (extension == ".ply") what = diagnose_ply(bytes);
    if (extension == ".stl") what = diagnose_stl(bytes);
    fail(source, "OpenMesh could not parse it as " + format + ": " + what);
  }
  const bool text_scanned = scan.vertices > 0;  // not for binary OFF
  if (text_scanned && (static_cast<long long>(soup.positions.size()) != scan.vertices ||
                       static_cast<long long>(soup.polygons.size()) != scan.faces))
    fail(source, "OpenMesh could not parse it as " + format + ": it read " +
                     count_of(static_cast<long long>(soup.positions.size()), "vertex", "vertices") + " and " +
                     count_of(static_cast<long long>(soup.polygons.size()), "face", "faces") + " where the file has " +
                     count_of(scan.vertices, "vertex", "vertices") + " and " + count_of(scan.faces, "face", "faces") +
                     "; try exporting it again");
  if (extension == ".stl") {
    if (soup.polygons.empty() && (!stl_is_binary(bytes) || stl_facet_count(bytes) == 0))
      fail(source, "OpenMesh could not parse it as STL: " +
                       (stl_is_binary(bytes) ? std::string("the binary STL declares 0 triangles, so it contains no faces")
                                             : diagnose_stl(bytes)));
    // OpenMesh merges equal positions and drops triangles left with a repeated vertex.
    collapsed_faces = int(std::max(0LL, stl_facet_count(bytes) - static_cast<long long>(soup.polygons.size())));
  }
  if (extension == ".ply" && soup.polygons.empty())
    fail(source, "OpenMesh could not parse it as PLY: it found no faces; " + diagnose_ply(bytes));
  return check_and_repair(std::move(soup.positions), soup.polygons, source, collapsed_faces);
}

}  // namespace paver
