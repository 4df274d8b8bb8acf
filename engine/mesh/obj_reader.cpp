#include "mesh/obj_reader.h"

#include "mesh/mesh_messages.h"
#include "mesh/reader_support.h"

#include <algorithm>
#include <climits>
#include <utility>
#include <unordered_set>

namespace paver {
namespace {

using namespace mesh_detail;

// Keeps the first of repeated corners, as Paver's OBJ reading always has: 'f 1 2 3 2' is the
// triangle 1 2 3, and 'f 1 1 2' collapses.
void remove_repeated_corners(std::vector<int>& corners) {
  if (corners.size() <= 16) {
    auto end = corners.end();
    for (auto it = corners.begin(); it != end; ++it) end = std::remove(it + 1, end, *it);
    corners.erase(end, corners.end());
    return;
  }
  std::unordered_set<int> seen;
  std::erase_if(corners, [&](int corner) { return !seen.insert(corner).second; });
}

// The vertex index of a face corner 'v[/vt[/vn]]'; the texture and normal indices are not used
// but must be integers.
long long corner_vertex(std::string_view corner, const std::string& source, int line) {
  const size_t slash = corner.find('/');
  const std::string_view vertex = corner.substr(0, slash);
  long long index = 0;
  if (vertex.empty())
    fail(source, at_line(line) + "face corner " + quoted(corner) + " has no vertex index");
  if (!parse_integer(vertex, index))
    fail(source, at_line(line) + quoted(corner) + " is not a vertex index");
  if (slash == std::string_view::npos) return index;
  std::string_view rest = corner.substr(slash + 1);
  while (true) {
    const size_t next = rest.find('/');
    const std::string_view part = rest.substr(0, next);
    long long ignored = 0;
    if (!part.empty() && !parse_integer(part, ignored))
      fail(source, at_line(line) + quoted(corner) + " is not a valid face corner (v/vt/vn)");
    if (next == std::string_view::npos) return index;
    rest = rest.substr(next + 1);
  }
}

// The lines that start with "v" and "f" (after blanks), as a cheap first pass over the text.
std::pair<long long, long long> count_vertex_and_face_lines(std::string_view text) {
  long long vertices = 0, faces = 0;
  std::size_t at = 0;
  while (at < text.size()) {
    while (at < text.size() && (text[at] == ' ' || text[at] == '\t')) ++at;
    if (at + 1 < text.size() && (text[at + 1] == ' ' || text[at + 1] == '\t')) {
      vertices += text[at] == 'v';
      faces += text[at] == 'f';
    }
    const std::size_t end = text.find('\n', at);
    at = end == std::string_view::npos ? text.size() : end + 1;
  }
  return {vertices, faces};
}

// The parts an OBJ's `o` and `g` lines name (PolygonSoup::group_sets), given to each face.
class PartNames {
public:
  void read(std::string_view keyword, const std::vector<std::string_view>& tokens) {
    if (keyword == "o") object_ = tokens.size() > 1 ? std::string(tokens[1]) : std::string();
    else groups_.assign(tokens.begin() + 1, tokens.end());
    changed_ = true;
  }
  // Before the face is added to `soup`: its names' set; faces before the first name have none, and
  // the per-face list is kept only once a name appears.
  void add_face(PolygonSoup& soup) {
    if (changed_) {
      changed_ = false;
      std::vector<std::string> names;
      if (!object_.empty()) names.push_back(object_);
      for (const std::string& name : groups_)
        if (name != "default" && std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
      set_ = -1;
      if (!names.empty()) {
        const auto known = std::find(soup.group_sets.begin(), soup.group_sets.end(), names);
        set_ = int(known - soup.group_sets.begin());
        if (known == soup.group_sets.end()) soup.group_sets.push_back(std::move(names));
      }
    }
    if (set_ >= 0 && soup.polygon_group.size() < soup.polygons.size()) soup.polygon_group.resize(soup.polygons.size(), -1);
    if (!soup.group_sets.empty()) soup.polygon_group.push_back(set_);
  }

private:
  std::string object_;
  std::vector<std::string> groups_;
  int set_ = -1;
  bool changed_ = false;
};

}  // namespace

PolygonSoup read_obj(std::string_view text, const std::string& source) {
  // A UTF-8 byte order mark (some Windows tools write one) hid the first line's keyword.
  if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.remove_prefix(3);
  // Another format under an .obj name read as an OBJ without faces ("not a point cloud"): say what
  // it is. A text OBJ starts with a printable character or a blank.
  const auto starts = [&](std::string_view magic) { return text.rfind(magic, 0) == 0; };
  if (starts("ply") || starts("OFF") || starts("solid "))
    fail(source, std::string("is not an OBJ file: it starts like ") +
                     (starts("ply") ? "a PLY" : starts("OFF") ? "an OFF" : "an STL") + " file; give it that extension");
  const unsigned char first = text.empty() ? ' ' : static_cast<unsigned char>(text.front());
  if (!((first >= 0x20 && first < 0x7f) || (first >= 0x09 && first <= 0x0d)))
    fail(source, "is not a text OBJ file (it starts with binary data); export the surface as OBJ, or give the file "
                 "its format's extension (.ply, .stl)");
  PolygonSoup soup;
  // Counted before any is stored, so that a file of millions of repeated lines is refused before
  // its memory is taken, and the arrays are allocated once.
  const auto [vertex_lines, face_lines] = count_vertex_and_face_lines(text);
  check_mesh_counts(source, vertex_lines, face_lines);
  soup.positions.reserve(std::size_t(vertex_lines));
  soup.polygons.reserve(std::size_t(face_lines));
  CoordinateReader coordinates(source, "vertex", "vertices", 1);
  // Indices past the vertices defined so far: allowed, but checked once the file is read.
  struct ForwardReference {
    int line;
    long long index;
  };
  std::vector<ForwardReference> forward;
  std::vector<std::string_view> tokens;
  std::vector<int> corners;
  PartNames parts;

  LineReader reader(text);
  std::string_view line;
  while (reader.next(line)) {
    line = line.substr(0, line.find('#'));
    split_tokens(line, tokens);
    if (tokens.empty()) continue;
    const int number = reader.number();
    const std::string_view keyword = tokens.front();
    const long long vertices = static_cast<long long>(soup.positions.size());
    if (keyword == "v") {
      if (tokens.size() < 4)
        fail(source, at_line(number) + "a 'v' line needs 3 coordinates (x y z) but has " +
                         std::to_string(tokens.size() - 1) + "; fix or delete the line");
      glm::dvec3 p;
      for (int i = 0; i < 3; ++i) p[i] = coordinates.text(tokens[size_t(i) + 1], number, vertices);
      soup.positions.push_back(p);  // anything after z (vertex colours) is ignored
    } else if (keyword == "vt") {
      double value = 0.0;
      if (tokens.size() < 3 || !parse_double(tokens[1], value) || !parse_double(tokens[2], value))
        fail(source, at_line(number) + "a 'vt' line needs 2 or 3 numbers (u v [w]); fix or delete the line");
    } else if (keyword == "g" || keyword == "o") {
      parts.read(keyword, tokens);
    } else if (keyword == "f") {
      if (tokens.size() < 4)
        fail(source, at_line(number) + "a face needs at least 3 vertices but this one has " +
                         std::to_string(tokens.size() - 1));
      if (tokens.size() - 1 > kMaxPolygonCorners)
        fail(source, at_line(number) + "the face has " + std::to_string(tokens.size() - 1) +
                         " corners; Paver reads faces of up to " + std::to_string(kMaxPolygonCorners) +
                         ": triangulate it in the modeller");
      corners.clear();
      for (size_t i = 1; i < tokens.size(); ++i) {
        long long index = corner_vertex(tokens[i], source, number);
        if (index == 0) fail(source, at_line(number) + "vertex index 0 is invalid: OBJ indices start at 1");
        if (index < 0) {
          if (vertices + index < 0)
            fail(source, at_line(number) + "relative index " + std::to_string(index) +
                             " points before the first vertex: only " +
                             count_of(vertices, "vertex is", "vertices are") + " defined above this line");
          index = vertices + index + 1;
        } else if (index > vertices) {
          forward.push_back({number, index});
          if (index > INT_MAX) index = 1;  // refused below: no file Paver reads defines that many
        }
        corners.push_back(int(index - 1));
      }
      remove_repeated_corners(corners);
      if (corners.size() < 3) {
        ++soup.collapsed_faces;
        continue;
      }
      parts.add_face(soup);
      soup.polygons.push_back(corners);
    }
  }
  const long long vertices = static_cast<long long>(soup.positions.size());
  for (const ForwardReference& reference : forward)
    if (reference.index > vertices)
      fail(source, at_line(reference.line) + "the face refers to vertex " + std::to_string(reference.index) +
                       " but the file defines only " + count_of(vertices, "vertex", "vertices") +
                       " (OBJ indices count from 1)");
  coordinates.finish();
  if (soup.polygons.empty() && soup.collapsed_faces == 0)
    fail(source, "contains no faces (" + count_of(vertices, "vertex", "vertices") +
                     ", no 'f' lines); Paver needs a surface, not a point cloud: export the faces too");
  return soup;
}

}  // namespace paver
