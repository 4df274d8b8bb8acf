#include "mesh/stl_reader.h"

#include "mesh/mesh_messages.h"
#include "mesh/reader_support.h"

#include <array>
#include <bit>
#include <cstdint>
#include <unordered_map>

namespace paver {
namespace {

using namespace mesh_detail;

// Welds corners by exact position (0 and -0 alike), keeping the first position seen, and adds
// each facet whose three corners stay distinct; a facet that collapses is counted, not added.
class Welder {
public:
  Welder(PolygonSoup& soup, size_t facets) : soup_(soup) { vertices_.reserve(facets); }

  void add_facet(const std::array<glm::dvec3, 3>& corners) {
    std::vector<int> facet(3);
    for (int c = 0; c < 3; ++c) facet[size_t(c)] = vertex(corners[size_t(c)]);
    if (facet[0] == facet[1] || facet[0] == facet[2] || facet[1] == facet[2]) ++soup_.collapsed_faces;
    else soup_.polygons.push_back(std::move(facet));
  }

private:
  struct Key {
    std::uint32_t bits[3];
    bool operator==(const Key& other) const = default;
  };
  struct KeyHash {
    size_t operator()(const Key& key) const {
      std::uint64_t h = ((std::uint64_t(key.bits[0]) << 32) | key.bits[1]) * 0x9e3779b97f4a7c15ull;
      h = (h ^ (h >> 32) ^ key.bits[2]) * 0xc2b2ae3d27d4eb4full;
      return size_t(h ^ (h >> 29));
    }
  };

  int vertex(const glm::dvec3& p) {
    Key key{};
    // Coordinates are single-precision values (CoordinateReader); +0.0f turns -0 into 0.
    for (int i = 0; i < 3; ++i) key.bits[i] = std::bit_cast<std::uint32_t>(static_cast<float>(p[i]) + 0.0f);
    const auto [it, added] = vertices_.try_emplace(key, int(soup_.positions.size()));
    if (added) soup_.positions.push_back(p);
    return it->second;
  }

  PolygonSoup& soup_;
  std::unordered_map<Key, int, KeyHash> vertices_;
};

bool starts_with_solid(std::string_view bytes) {
  return equals_lowercase(trim(bytes.substr(0, 80)).substr(0, 5), "solid");
}

PolygonSoup read_binary(std::string_view bytes, const std::string& source) {
  const std::uint64_t facets = load_unsigned(bytes, 80, 4, false);  // matches the length: see read_stl
  if (facets == 0) fail(source, "contains no faces (the STL file has no triangles)");
  PolygonSoup soup;
  soup.polygons.reserve(facets);
  Welder welder(soup, facets);
  CoordinateReader coordinates(source, "facet", "facets", 0);
  std::array<glm::dvec3, 3> corners;
  for (std::uint64_t f = 0; f < facets; ++f) {
    const std::uint64_t at = 84 + 50 * f + 12;  // after the facet normal
    for (int c = 0; c < 3; ++c)
      for (int i = 0; i < 3; ++i) {
        const std::uint64_t offset = at + 12 * c + 4 * i;
        corners[size_t(c)][i] = coordinates.binary(load_float(bytes, offset, false), offset, static_cast<long long>(f));
      }
    welder.add_facet(corners);
  }
  coordinates.finish();
  return soup;
}

PolygonSoup read_ascii(std::string_view text, const std::string& source) {
  enum class State { BeforeSolid, InSolid, InFacet, InLoop, LoopDone, FacetDone, AfterSolid };
  State state = State::BeforeSolid;
  PolygonSoup soup;
  Welder welder(soup, text.size() / 256);  // a facet takes about 250 bytes of text
  CoordinateReader coordinates(source, "facet", "facets", 0);
  std::array<glm::dvec3, 3> corners;
  long long facet = 0;
  int corner = 0;
  LineReader reader(text);
  std::string_view line;
  std::vector<std::string_view> tokens;
  while (reader.next(line)) {
    split_tokens(line, tokens);
    if (tokens.empty()) continue;
    const int number = reader.number();
    const std::string_view keyword = tokens[0], second = tokens.size() > 1 ? tokens[1] : std::string_view();
    const auto is = equals_lowercase;  // STL keywords in any case
    auto expected = [&](const std::string& what) {
      fail(source, at_line(number) + "expected " + what + " in ASCII STL, found " +
                       quoted(line));
    };
    switch (state) {
      case State::BeforeSolid:
      case State::AfterSolid:
        if (!is(keyword, "solid")) expected(state == State::BeforeSolid ? "'solid'" : "'solid' or the end of the file");
        state = State::InSolid;
        break;
      case State::InSolid:
        if (is(keyword, "endsolid")) {
          state = State::AfterSolid;
          break;
        }
        if (!is(keyword, "facet") || (tokens.size() != 1 && (!is(second, "normal") || tokens.size() != 5)))
          expected("'facet normal <nx> <ny> <nz>' or 'endsolid'");
        for (size_t i = 2; i < tokens.size(); ++i) {
          double ignored = 0.0;
          if (!parse_double(tokens[i], ignored))
            fail(source, at_line(number) + quoted(tokens[i]) + " is not a number");
        }
        state = State::InFacet;
        break;
      case State::InFacet:
        if (!is(keyword, "outer") || !is(second, "loop") || tokens.size() != 2) expected("'outer loop'");
        state = State::InLoop;
        corner = 0;
        break;
      case State::InLoop:
        if (!is(keyword, "vertex"))
          expected("'vertex <x> <y> <z>' (corner " + std::to_string(corner + 1) + " of facet " +
                   std::to_string(facet) + ", counting from 0)");
        if (tokens.size() != 4)
          fail(source, at_line(number) + "a 'vertex' line needs 3 coordinates (x y z) but has " +
                           std::to_string(tokens.size() - 1));
        for (int i = 0; i < 3; ++i) corners[size_t(corner)][i] = coordinates.text(tokens[size_t(i) + 1], number, facet);
        if (++corner == 3) state = State::LoopDone;
        break;
      case State::LoopDone:
        if (!is(keyword, "endloop") || tokens.size() != 1) expected("'endloop' (a facet is a triangle: 3 vertices)");
        state = State::FacetDone;
        break;
      case State::FacetDone:
        if (!is(keyword, "endfacet") || tokens.size() != 1) expected("'endfacet'");
        welder.add_facet(corners);
        ++facet;
        state = State::InSolid;
        break;
    }
  }
  if (state != State::AfterSolid)
    fail(source, "the ASCII STL text ends inside " +
                     (state == State::InSolid ? std::string("the solid (no 'endsolid')")
                                              : "facet " + std::to_string(facet) + " (counting from 0)") +
                     "; truncated file?");
  coordinates.finish();
  if (facet == 0) fail(source, "contains no faces (the STL file has no triangles)");
  return soup;
}

}  // namespace

PolygonSoup read_stl(std::string_view bytes, const std::string& source) {
  const std::string cannot = "could not parse it as STL: ";
  if (bytes.size() >= 84 && bytes.size() == 84 + 50 * load_unsigned(bytes, 80, 4, false))
    return read_binary(bytes, source);
  // ASCII STL is text: a NUL byte means a binary file that happens to start with 'solid'.
  if (starts_with_solid(bytes) && bytes.find('\0') == std::string_view::npos) return read_ascii(bytes, source);
  if (bytes.size() < 84)
    fail(source, cannot + "it does not start with 'solid' (ASCII STL) and is too short (" +
                     std::to_string(bytes.size()) + " bytes) for binary STL, which has an 84-byte header");
  const std::uint64_t triangles = load_unsigned(bytes, 80, 4, false);
  fail(source, cannot + "binary STL size mismatch: the triangle count at byte offset 80 declares " +
                   std::to_string(triangles) + " triangles, which take " + std::to_string(84 + 50 * triangles) +
                   " bytes, but the file has " + std::to_string(bytes.size()) +
                   " bytes (truncated or not an STL file)");
}

}  // namespace paver
