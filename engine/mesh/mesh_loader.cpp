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
#include "mesh/mesh_loader.h"

#include "core/input_error.h"

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
                             " points before the first vertex: only " +
                             count_of(vertices, "vertex is", "vertices are") +
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

  if (data.empty())
    fail(source, "the file ends after the OFF header; it contains no faces (the counts line is missing)");
  split_tokens(data[0].text, tokens);
  const int counts_line = data[0].number;
  long long counts[3] = {0, 0, 0};
  bool counts_ok = tokens.size() == 3;
  for (size_t i = 0; i < 3 && counts_ok; ++i)
    counts_ok = parse_integer(tokens[i], counts[i]) && counts[i] >= 0 && counts[i] <= INT_MAX;
  if (!counts_ok)
    fail(source, at_line(counts_line) +
                     "expected the counts '<vertices> <faces> <edges>' after the OFF header, found '" +
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
// STL and PLY: explanations for when OpenMesh fails, and guards for where it would crash

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

// PLY: the header is read strictly and the data walked before OpenMesh sees the file, because
// OpenMesh's PLY reader crashes on some malformed headers (a property before any element) and
// hangs on malformed ASCII data (its stream fails and it keeps reading uninitialised counts).
struct PlyProperty {
  std::string name;
  bool list = false;
  size_t size = 0;        // scalar size, or the list's item size
  size_t count_size = 0;  // lists: size of the length prefix
  bool integer = false;   // the scalar or item type is an integer type
};

struct PlyElement {
  std::string name;
  long long count = 0;
  std::vector<PlyProperty> properties;
};

struct PlyHeader {
  std::string error;  // why the header is unusable, with its line; empty if it is well-formed
  std::string format;
  std::vector<PlyElement> elements;
  size_t data_offset = 0;
  int data_line = 0;  // line number of the first data line (ASCII)
  long long vertices = 0, faces = 0;
};

bool ply_type_is_integer(std::string_view type) {
  return type != "float" && type != "float32" && type != "double" && type != "float64";
}

// Size in bytes of a PLY scalar type; 0 if unknown.
size_t ply_type_size(std::string_view type) {
  if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
  if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
  if (type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" || type == "float32")
    return 4;
  if (type == "double" || type == "float64") return 8;
  return 0;
}

bool is_face_index_list(const PlyElement& element, const PlyProperty& property) {
  return element.name == "face" && property.list &&
         (property.name == "vertex_indices" || property.name == "vertex_index");
}

PlyHeader parse_ply_header(std::string_view bytes) {
  PlyHeader header;
  LineReader reader(bytes);
  std::string_view line;
  std::vector<std::string_view> tokens;
  if (!reader.next(line) || (line != "ply" && line != "PLY")) {
    header.error = "it does not start with the 'ply' magic line";
    return header;
  }
  auto bad = [&](const std::string& what) {
    header.error = at_line(reader.number()) + what;
    return header;
  };
  while (reader.next(line)) {
    split_tokens(line, tokens);
    if (tokens.empty()) continue;
    const std::string_view keyword = tokens[0];
    // OpenMesh takes the three words after 'ply' as the format line, whatever they are.
    if (header.format.empty() && keyword != "format") return bad("expected the 'format' line right after 'ply'");
    if (keyword == "comment") continue;
    if (keyword == "obj_info") {
      // OpenMesh reads obj_info text word by word, as if each word were a keyword.
      for (std::string_view word : tokens)
        if (word == "element" || word == "property" || word == "end_header" || word == "comment")
          return bad("OpenMesh misreads an obj_info line containing '" + std::string(word) + "'; delete the line");
      continue;
    }
    if (keyword == "end_header") {
      if (header.format.empty()) return bad("the header has no 'format' line");
      const PlyElement* vertex = nullptr;
      const PlyElement* face = nullptr;
      for (const PlyElement& element : header.elements) {
        if (element.name == "vertex") vertex = &element;
        if (element.name == "face") face = &element;
      }
      int axes = 0;
      for (const PlyProperty& property : vertex ? vertex->properties : std::vector<PlyProperty>())
        axes += !property.list && (property.name == "x" || property.name == "y" || property.name == "z");
      if (axes != 3) return bad("the header declares no vertex element with x, y and z properties");
      if (face && std::none_of(face->properties.begin(), face->properties.end(),
                               [&](const PlyProperty& p) { return is_face_index_list(*face, p); }))
        return bad("the face element has no 'vertex_indices' list");
      const size_t end = bytes.find('\n', size_t(line.data() - bytes.data()));
      header.data_offset = end == std::string_view::npos ? bytes.size() : end + 1;
      header.data_line = reader.number() + 1;
      return header;
    }
    if (keyword == "format") {
      double version = 0.0;
      if (!header.format.empty() || tokens.size() != 3 ||
          (tokens[1] != "ascii" && tokens[1] != "binary_little_endian" && tokens[1] != "binary_big_endian") ||
          !parse_double(tokens[2], version) || version != 1.0)
        return bad("expected 'format ascii|binary_little_endian|binary_big_endian 1.0'");
      header.format = std::string(tokens[1]);
    } else if (keyword == "element") {
      PlyElement& element = header.elements.emplace_back();
      if (tokens.size() != 3 || !parse_integer(tokens[2], element.count) || element.count < 0 ||
          element.count > INT_MAX)
        return bad("expected 'element <name> <count>'");
      element.name = std::string(tokens[1]);
      if (element.name == "vertex") header.vertices = element.count;
      if (element.name == "face") header.faces = element.count;
    } else if (keyword == "property") {
      if (header.elements.empty()) return bad("a property before any element");
      PlyElement& element = header.elements.back();
      PlyProperty property;
      if (tokens.size() == 5 && tokens[1] == "list") {
        property.list = true;
        property.count_size = ply_type_size(tokens[2]);
        property.size = ply_type_size(tokens[3]);
        property.integer = ply_type_is_integer(tokens[3]);
        property.name = std::string(tokens[4]);
        if (property.count_size == 0 || property.size == 0) return bad("unknown list type");
        if (tokens[2] != "uchar" && tokens[2] != "uint8" && tokens[2] != "uint16" && tokens[2] != "int")
          return bad("OpenMesh reads list lengths of type uchar, uint8, uint16 or int only, not '" +
                     std::string(tokens[2].substr(0, 40)) + "'");
      } else if (tokens.size() == 3 && tokens[1] != "list") {
        property.size = ply_type_size(tokens[1]);
        property.integer = ply_type_is_integer(tokens[1]);
        property.name = std::string(tokens[2]);
        if (property.size == 0) return bad("unknown property type '" + std::string(tokens[1].substr(0, 40)) + "'");
      } else {
        return bad("expected 'property <type> <name>' or 'property list <count type> <item type> <name>'");
      }
      // OpenMesh skips unknown properties one value at a time, so it can only read the lists it knows.
      if (property.list && !is_face_index_list(element, property) &&
          !(element.name == "face" && property.name == "texcoord"))
        return bad("OpenMesh cannot read the list property '" + property.name + "' of element '" + element.name +
                   "'; export without it");
      element.properties.push_back(std::move(property));
    } else {
      return bad("'" + std::string(keyword.substr(0, 40)) + "' is not a PLY header keyword");
    }
  }
  header.error = "the header has no 'end_header' line";
  return header;
}

// Whitespace-separated tokens of a text, with the line each is on.
class TokenReader {
public:
  TokenReader(std::string_view text, int first_line) : lines_(text), first_line_(first_line) {}
  bool next(std::string_view& token) {
    while (index_ >= tokens_.size()) {
      std::string_view line;
      if (!lines_.next(line)) return false;
      split_tokens(line, tokens_);
      index_ = 0;
    }
    token = tokens_[index_++];
    return true;
  }
  int line() const { return first_line_ + lines_.number() - 1; }

private:
  LineReader lines_;
  int first_line_;
  std::vector<std::string_view> tokens_;
  size_t index_ = 0;
};

// Walks the ASCII data as OpenMesh will, naming the line of the first value it could not read.
void prescan_ply_ascii(std::string_view bytes, const PlyHeader& header, const std::string& source) {
  TokenReader reader(bytes.substr(header.data_offset), header.data_line);
  NonFinite nonfinite;
  std::string_view token;
  for (const PlyElement& element : header.elements) {
    for (long long record = 0; record < element.count; ++record) {
      bool counted = false;
      for (const PlyProperty& property : element.properties) {
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
                             element.name + " " + std::to_string(record) + ", found '" +
                             std::string(token.substr(0, 40)) + "'");
        }
        for (long long i = 0; i < length; ++i) {
          next();
          double value = 0.0;
          long long index = 0;
          const bool ok = property.integer ? parse_integer(token, index) : parse_double(token, value);
          if (!ok)
            fail(source, at_line(reader.line()) + "'" + std::string(token.substr(0, 40)) + "' is not " +
                             (property.integer ? "an integer" : "a number") + " (property '" + property.name +
                             "' of " + element.name + " " + std::to_string(record) + ")");
          if (is_face_index_list(element, property) && (index < 0 || index >= header.vertices))
            fail(source, at_line(reader.line()) + "face " + std::to_string(record) +
                             " (counting from 0) refers to vertex " +
                             std::to_string(index) + ", but the header declares " +
                             count_of(header.vertices, "vertex", "vertices") + " (PLY indices count from 0)");
          if (element.name == "vertex" && !property.integer &&
              (property.name == "x" || property.name == "y" || property.name == "z")) {
            check_single_precision(source, reader.line(), token, value);  // OpenMesh reads floats here
            nonfinite.check(token, value, reader.line(), record, counted);
          }
        }
      }
    }
    if (element.name == "face") break;  // OpenMesh stops reading after the faces
  }
  if (nonfinite.count > 0)
    fail(source, at_line(nonfinite.first_line) + "vertex " + std::to_string(nonfinite.first_vertex) +
                     " (counting from 0) has a non-finite coordinate '" + nonfinite.first_token + "'; " +
                     count_of(nonfinite.count, "vertex has", "vertices have") +
                     " NaN or infinite coordinates: fix them in the modelling tool and export again");
}

// Walks the binary records, so that a truncated file or a corrupt list length is reported
// instead of read past.
std::string check_ply_binary(std::string_view bytes, const PlyHeader& header) {
  const bool big_endian = header.format == "binary_big_endian";
  auto read_unsigned = [&](size_t at, size_t size) {
    std::uint64_t value = 0;
    for (size_t i = 0; i < size; ++i)
      value |= std::uint64_t(static_cast<unsigned char>(bytes[at + (big_endian ? size - 1 - i : i)])) << (8 * i);
    return value;
  };
  size_t at = header.data_offset;
  for (const PlyElement& element : header.elements) {
    for (long long record = 0; record < element.count; ++record) {
      for (const PlyProperty& property : element.properties) {
        std::uint64_t length = 1;
        if (property.list) {
          if (bytes.size() - at < property.count_size) at = bytes.size() + 1;
          else {
            length = read_unsigned(at, property.count_size);
            at += property.count_size;
          }
        }
        if (at > bytes.size() || (bytes.size() - at) / property.size < length)
          return "binary PLY size mismatch: the data ends inside " + element.name + " " + std::to_string(record) +
                 " (counting from 0) of the " + std::to_string(element.count) + " the header declares; the file has " +
                 std::to_string(bytes.size()) + " bytes (truncated file?)";
        at += property.size * length;
      }
    }
    if (element.name == "face") break;  // OpenMesh stops reading after the faces
  }
  return {};
}

std::string diagnose_ply(std::string_view bytes) {
  const PlyHeader header = parse_ply_header(bytes);
  if (!header.error.empty()) return header.error;
  return "the header declares " + count_of(header.vertices, "vertex", "vertices") + " and " +
         count_of(header.faces, "face", "faces") + ", but the data does not match them";
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

// The triangles' sides grouped by undirected edge (sorting, not hashing: faster at this size).
struct Edges {
  std::vector<Side> sides;                        // sorted by key
  std::vector<std::pair<size_t, size_t>> ranges;  // per edge, its [begin, end) in `sides`
};

Edges collect_edges(const std::vector<glm::ivec3>& triangles) {
  Edges edges;
  edges.sides.reserve(triangles.size() * 3);
  for (int f = 0; f < int(triangles.size()); ++f)
    for (int c = 0; c < 3; ++c) edges.sides.push_back({edge_key(triangles[f][c], triangles[f][(c + 1) % 3]), f, c});
  std::sort(edges.sides.begin(), edges.sides.end(), [](const Side& a, const Side& b) {
    return a.key != b.key ? a.key < b.key : a.triangle != b.triangle ? a.triangle < b.triangle : a.corner < b.corner;
  });
  edges.ranges.reserve(edges.sides.size() / 2 + 1);
  for (size_t begin = 0; begin < edges.sides.size();) {
    size_t end = begin + 1;
    while (end < edges.sides.size() && edges.sides[end].key == edges.sides[begin].key) ++end;
    edges.ranges.emplace_back(begin, end);
    begin = end;
  }
  return edges;
}

// Where each face's sides lead: the face across side c of face f, and whether that face runs the
// shared edge in the same direction (an orientation conflict).
struct Adjacency {
  std::vector<int> neighbour;         // #F*3, -1 on the boundary
  std::vector<char> same_direction;   // #F*3
};

Adjacency face_adjacency(const std::vector<glm::ivec3>& triangles, const Edges& edges) {
  Adjacency adjacency{std::vector<int>(triangles.size() * 3, -1), std::vector<char>(triangles.size() * 3, 0)};
  for (const auto& [begin, end] : edges.ranges) {
    if (end - begin != 2) continue;
    const Side& s = edges.sides[begin];
    const Side& r = edges.sides[begin + 1];
    const bool same = triangles[r.triangle][r.corner] == triangles[s.triangle][s.corner];
    adjacency.neighbour[s.triangle * 3 + s.corner] = r.triangle;
    adjacency.neighbour[r.triangle * 3 + r.corner] = s.triangle;
    adjacency.same_direction[s.triangle * 3 + s.corner] = adjacency.same_direction[r.triangle * 3 + r.corner] = same;
  }
  return adjacency;
}

// `polygons` must index `positions`, and every position be finite: otherwise nothing else is
// meaningful.
void check_indices_and_coordinates(const std::vector<glm::dvec3>& positions,
                                   const std::vector<std::vector<int>>& polygons, const std::string& source) {
  const long long vertex_count = static_cast<long long>(positions.size());
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
}

// Below this area a face counts as degenerate: relative to the size of the referenced geometry.
double degenerate_area(const std::vector<glm::dvec3>& positions, const std::vector<std::vector<int>>& polygons) {
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (const std::vector<int>& polygon : polygons)
    for (int index : polygon) {
      lo = glm::min(lo, positions[index]);
      hi = glm::max(hi, positions[index]);
    }
  const double diagonal = polygons.empty() ? 0.0 : glm::length(hi - lo);
  return 1e-12 * diagonal * diagonal;
}

struct Components {
  int count = 0;
  long long dropped_faces = 0;
};

// Keeps the triangles of the largest component (through shared vertices; see the top comment).
Components keep_largest_component(std::vector<glm::ivec3>& triangles, size_t vertex_count) {
  DisjointSets sets(vertex_count);
  for (const glm::ivec3& t : triangles) {
    sets.unite(t.x, t.y);
    sets.unite(t.x, t.z);
  }
  std::vector<int> faces(vertex_count, 0);  // per root
  for (const glm::ivec3& t : triangles) ++faces[sets.find(t.x)];
  Components components;
  int largest = -1;
  for (size_t root = 0; root < vertex_count; ++root) {
    if (faces[root] == 0) continue;
    ++components.count;
    if (largest < 0 || faces[root] > faces[largest]) largest = int(root);
  }
  if (components.count > 1) {
    const size_t before = triangles.size();
    std::erase_if(triangles, [&](const glm::ivec3& t) { return sets.find(t.x) != largest; });
    components.dropped_faces = static_cast<long long>(before - triangles.size());
  }
  return components;
}

// Every edge on at most 2 faces, and the faces around every vertex one fan.
void check_manifold(const std::vector<glm::ivec3>& triangles, const Edges& edges,
                    const std::vector<glm::dvec3>& positions, const std::string& source, const std::string& note) {
  int bad_edges = 0;
  size_t example_edge = 0;
  for (size_t e = 0; e < edges.ranges.size(); ++e) {
    if (edges.ranges[e].second - edges.ranges[e].first <= 2) continue;
    if (bad_edges++ == 0) example_edge = e;
  }
  if (bad_edges > 0) {
    const auto [begin, end] = edges.ranges[example_edge];
    const Side& side = edges.sides[begin];
    const glm::ivec3& t = triangles[side.triangle];
    fail(source, "has " + count_of(bad_edges, "non-manifold edge", "non-manifold edges") +
                     " (shared by more than 2 faces), e.g. " +
                     edge_between(t[side.corner], t[(side.corner + 1) % 3], positions) + ", shared by " +
                     std::to_string(end - begin) +
                     " faces; Paver needs a manifold surface: remove the extra (duplicated or fin) faces" + note);
  }

  // Corners of the same vertex joined across shared edges form that vertex's fans.
  DisjointSets corners(triangles.size() * 3);
  for (const auto& [begin, end] : edges.ranges) {
    if (end - begin != 2) continue;
    const Side& s = edges.sides[begin];
    const Side& r = edges.sides[begin + 1];
    const glm::ivec3& ts = triangles[s.triangle];
    const glm::ivec3& tr = triangles[r.triangle];
    for (int vertex : {ts[s.corner], ts[(s.corner + 1) % 3]})
      corners.unite(s.triangle * 3 + corner_of(ts, vertex), r.triangle * 3 + corner_of(tr, vertex));
  }
  std::vector<int> fans(positions.size(), 0);
  for (int corner = 0; corner < int(triangles.size() * 3); ++corner)
    if (corners.find(corner) == corner) ++fans[triangles[corner / 3][corner % 3]];
  int bad_vertices = 0, example_vertex = -1;
  for (size_t v = 0; v < fans.size(); ++v) {
    if (fans[v] <= 1) continue;
    if (bad_vertices++ == 0) example_vertex = int(v);
  }
  if (bad_vertices > 0)
    fail(source, "has " + count_of(bad_vertices, "non-manifold vertex", "non-manifold vertices") + ", e.g. vertex " +
                     std::to_string(example_vertex) + " (counting from 0) at " +
                     format_point(positions[example_vertex]) + ", where " + std::to_string(fans[example_vertex]) +
                     " separate fans of faces meet at a single point (like two cones touching at their tips, or a "
                     "bowtie); Paver needs a manifold surface: pull the pieces apart or split the vertex" +
                     note);
}

// Flips faces so that neighbours run their shared edge in opposite directions, keeping the
// orientation most faces already have. Returns how many faces were flipped.
long long orient_consistently(std::vector<glm::ivec3>& triangles, const Edges& edges,
                              const std::vector<glm::dvec3>& positions, const std::string& source,
                              const std::string& note) {
  const Adjacency adjacency = face_adjacency(triangles, edges);
  const int face_count = int(triangles.size());
  std::vector<signed char> flip(size_t(face_count), -1);  // -1: not reached yet
  std::vector<int> queue;
  queue.reserve(size_t(face_count));
  for (int seed = 0; seed < face_count; ++seed) {
    if (flip[seed] >= 0) continue;
    flip[seed] = 0;
    queue.assign(1, seed);
    for (size_t head = 0; head < queue.size(); ++head) {
      const int f = queue[head];
      for (int c = 0; c < 3; ++c) {
        const int g = adjacency.neighbour[f * 3 + c];
        if (g < 0) continue;
        const signed char wanted = static_cast<signed char>(flip[f] ^ adjacency.same_direction[f * 3 + c]);
        if (flip[g] < 0) {
          flip[g] = wanted;
          queue.push_back(g);
        } else if (flip[g] != wanted) {
          fail(source, "is not orientable (like a Moebius strip): its faces cannot be oriented consistently, as "
                       "seen at " +
                           edge_between(triangles[f][c], triangles[f][(c + 1) % 3], positions) +
                           "; Paver needs a two-sided surface" + note);
        }
      }
    }
  }
  long long flipped = std::count(flip.begin(), flip.end(), 1);
  const bool invert = 2 * flipped > face_count;
  if (invert) flipped = face_count - flipped;
  for (int f = 0; f < face_count; ++f)
    if ((flip[f] == 1) != invert) std::swap(triangles[f].y, triangles[f].z);
  return flipped;
}

// The one boundary loop of consistently oriented, manifold triangles, following the direction of
// its sides and starting at its lowest vertex.
std::vector<int> single_boundary_loop(const std::vector<glm::ivec3>& triangles, const Edges& edges,
                                      size_t vertex_count, const std::string& source, const std::string& note) {
  std::vector<int> next(vertex_count, -1);
  int first = -1;
  for (const auto& [begin, end] : edges.ranges) {
    if (end - begin != 1) continue;
    // The face may have been flipped since `edges` was collected: read the direction off the face.
    const glm::ivec3& t = triangles[edges.sides[begin].triangle];
    int c = 0;
    while (edge_key(t[c], t[(c + 1) % 3]) != edges.sides[begin].key) ++c;
    next[t[c]] = t[(c + 1) % 3];
    if (first < 0 || t[c] < first) first = t[c];
  }
  if (first < 0)
    fail(source, "is a closed surface (it has no boundary edges); Paver needs an open surface with one boundary "
                 "loop; cut it open first" +
                     note);
  std::vector<char> visited(vertex_count, 0);
  std::vector<int> loop_sizes;
  std::vector<int> loop;
  for (int start = 0; start < int(vertex_count); ++start) {
    if (next[start] < 0 || visited[start]) continue;
    int size = 0;
    for (int v = start; v >= 0 && !visited[v]; v = next[v]) {
      visited[v] = 1;
      if (start == first) loop.push_back(v);
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
                     note);
  }
  return loop;
}

LoadedSurface check_and_repair(std::vector<glm::dvec3> positions, const std::vector<std::vector<int>>& polygons,
                               const std::string& source, int collapsed_faces) {
  LoadedSurface loaded;
  if (polygons.empty() && collapsed_faces == 0)
    fail(source, "contains no faces (" + count_of(static_cast<long long>(positions.size()), "vertex", "vertices") +
                     "); Paver needs a surface, not a point cloud: export the faces too");
  check_indices_and_coordinates(positions, polygons, source);

  Triangulation triangulation = triangulate(positions, polygons, degenerate_area(positions, polygons));
  std::vector<glm::ivec3>& triangles = triangulation.triangles;
  loaded.dropped_degenerate_faces = triangulation.degenerate + collapsed_faces;
  const std::string degenerate = count_of(loaded.dropped_degenerate_faces, "degenerate face", "degenerate faces");
  if (triangles.empty())
    fail(source,
         "contains no faces after dropping " + degenerate + " (zero area or repeated vertices); check the export");
  if (loaded.dropped_degenerate_faces > 0)
    loaded.warnings.push_back(source + ": dropped " + degenerate + " (zero area or repeated vertices)");

  std::vector<char> used(positions.size(), 0);
  for (const glm::ivec3& t : triangles) used[t.x] = used[t.y] = used[t.z] = 1;
  const long long unreferenced = std::count(used.begin(), used.end(), 0);
  if (unreferenced > 0)
    loaded.warnings.push_back(source + ": dropped " +
                              count_of(unreferenced, "unreferenced vertex", "unreferenced vertices") +
                              " (not used by any face)");

  const Components components = keep_largest_component(triangles, positions.size());
  std::string note;  // appended to topology errors when other components were dropped
  if (components.count > 1) {
    loaded.dropped_components = components.count - 1;
    loaded.warnings.push_back(source + ": the surface has " + std::to_string(components.count) +
                              " connected components; kept the largest (" +
                              count_of(static_cast<long long>(triangles.size()), "face", "faces") +
                              ") and dropped the other " + std::to_string(components.count - 1) + " (" +
                              count_of(components.dropped_faces, "face", "faces") + ")");
    note = " (in its largest connected component, the one Paver keeps; the file has " +
           std::to_string(components.count) + ")";
  }

  const Edges edges = collect_edges(triangles);
  check_manifold(triangles, edges, positions, source, note);
  const long long flipped = orient_consistently(triangles, edges, positions, source, note);
  if (flipped > 0)
    loaded.warnings.push_back(source + ": reoriented " + count_of(flipped, "face", "faces") +
                              " to match their neighbours");
  const std::vector<int> loop = single_boundary_loop(triangles, edges, positions.size(), source, note);

  // Compact the vertices to those the kept faces use.
  std::fill(used.begin(), used.end(), 0);
  for (const glm::ivec3& t : triangles) used[t.x] = used[t.y] = used[t.z] = 1;
  std::vector<int> new_index(positions.size(), -1);
  SurfaceMesh& mesh = loaded.mesh;
  for (size_t v = 0; v < positions.size(); ++v)
    if (used[v]) {
      new_index[v] = int(mesh.positions.size());
      mesh.positions.push_back(positions[v]);
    }

  // One boundary loop on a connected, orientable surface: a disk exactly when V - E + F = 1.
  const long long euler = static_cast<long long>(mesh.positions.size()) -
                          static_cast<long long>(edges.ranges.size()) + static_cast<long long>(triangles.size());
  if (euler != 1)
    fail(source, "is not a topological disk: it has one boundary loop but " +
                     count_of((1 - euler) / 2, "handle", "handles") + " (V - E + F = " + std::to_string(euler) +
                     ", a disk has 1); Paver needs a disk-like surface: cut through the handles or fill them" + note);

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
    if (header.format == "ascii") {
      prescan_ply_ascii(bytes, header, source);
    } else if (const std::string error = check_ply_binary(bytes, header); !error.empty()) {
      fail(source, "OpenMesh could not parse it as PLY: " + error);
    }
  }
  int collapsed_faces = scan.collapsed_faces;

  PolygonSoup soup;
  bool read = false;
  {
    const OpenMeshReadLock lock;
    OpenMesh::IO::Options options;  // positions and faces only
    read = OpenMesh::IO::IOManager().read(source, soup, options);
  }
  std::string format = extension.substr(1);
  for (char& c : format) c = char(std::toupper(static_cast<unsigned char>(c)));
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
    const long long facets = stl_facet_count(bytes);
    if (soup.positions.empty() && facets == 0)
      fail(source, starts_with_solid(bytes) || stl_is_binary(bytes)
                       ? "contains no faces (the STL file has no triangles)"
                       : "OpenMesh could not parse it as STL: " + diagnose_stl(bytes));
    if (soup.positions.empty()) fail(source, "OpenMesh could not parse it as STL: " + diagnose_stl(bytes));
    // OpenMesh merges equal positions and drops triangles left with a repeated vertex.
    collapsed_faces = int(std::max(0LL, facets - static_cast<long long>(soup.polygons.size())));
  }
  if (extension == ".ply" && soup.polygons.empty())
    fail(source, "OpenMesh could not parse it as PLY: it found no faces; " + diagnose_ply(bytes));
  return check_and_repair(std::move(soup.positions), soup.polygons, source, collapsed_faces);
}

}  // namespace paver
