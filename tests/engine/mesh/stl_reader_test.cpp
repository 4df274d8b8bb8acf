// Tests for engine/mesh/stl_reader.cpp: ASCII and binary STL, welding of corners, and refusals
// that name the place (line, or byte offset and facet).
#include "mesh/stl_reader.h"

#include "byte_writer.h"
#include "input_error_assertions.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace paver {
namespace {

using test::ByteWriter;
using test::Contains;
using test::error_of;

using Facet = std::array<glm::vec3, 3>;

std::string binary_stl(const std::vector<Facet>& facets, std::string header = "binary STL from a test") {
  header.resize(80, ' ');
  ByteWriter out;
  out.text(header).put(std::uint32_t(facets.size()));
  for (const Facet& facet : facets) {
    out.put(0.0f).put(0.0f).put(1.0f);
    for (const glm::vec3& corner : facet) out.put(corner.x).put(corner.y).put(corner.z);
    out.put(std::uint16_t(0));
  }
  return out.bytes();
}

const std::vector<Facet> kSquare = {{glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(1, 1, 0)},
                                    {glm::vec3(0, 0, 0), glm::vec3(1, 1, 0), glm::vec3(0, 1, 0)}};

std::string ascii_facet(const char* a, const char* b, const char* c) {
  return std::string("  facet normal 0 0 1\n    outer loop\n      vertex ") + a + "\n      vertex " + b +
         "\n      vertex " + c + "\n    endloop\n  endfacet\n";
}

TEST(StlReader, BinaryCornersAreWeldedByExactPosition) {
  std::vector<Facet> facets = kSquare;
  facets[1][0] = glm::vec3(-0.0f, 0.0f, -0.0f);  // the same position as (0, 0, 0)
  const PolygonSoup soup = read_stl(binary_stl(facets), "square.stl");
  ASSERT_EQ(soup.positions.size(), 4u);
  EXPECT_EQ(soup.positions[3], glm::dvec3(0, 1, 0));
  EXPECT_EQ(soup.polygons, (std::vector<std::vector<int>>{{0, 1, 2}, {0, 2, 3}}));
  EXPECT_EQ(soup.collapsed_faces, 0);
}

TEST(StlReader, FacetWhoseCornersWeldIsCountedNotAdded) {
  std::vector<Facet> facets = kSquare;
  facets.push_back({glm::vec3(1, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)});
  facets.push_back({glm::vec3(1, 0, 0), glm::vec3(1, 0, 1e-7f), glm::vec3(0, 1, 0)});  // not equal: kept
  const PolygonSoup soup = read_stl(binary_stl(facets), "square.stl");
  EXPECT_EQ(soup.polygons.size(), 3u);
  EXPECT_EQ(soup.collapsed_faces, 1);
}

TEST(StlReader, TruncatedBinaryIsRefused) {
  std::string bytes = binary_stl(kSquare);  // 84 + 2 x 50 = 184 bytes
  bytes.resize(bytes.size() - 7);
  const std::string message = error_of([&] { read_stl(bytes, "cut.stl"); });
  EXPECT_TRUE(Contains(message, "cut.stl: could not parse it as STL: binary STL size mismatch"));
  EXPECT_TRUE(Contains(message, "byte offset 80 declares 2 triangles, which take 184 bytes"));
  EXPECT_TRUE(Contains(message, "the file has 177 bytes"));
}

TEST(StlReader, TruncatedBinaryStartingWithSolidIsNotTakenForText) {
  // Some exporters start the binary header with "solid"; the binary data gives it away.
  std::string bytes = binary_stl(kSquare, "solid exported by a CAD tool");
  bytes.resize(bytes.size() - 50);
  const std::string message = error_of([&] { read_stl(bytes, "cut.stl"); });
  EXPECT_TRUE(Contains(message, "binary STL size mismatch"));
  EXPECT_TRUE(Contains(message, "2 triangles"));
}

TEST(StlReader, BinaryNanNamesFacetAndByteOffset) {
  std::vector<Facet> facets = kSquare;
  facets[1][2].x = std::nanf("");
  const std::string message = error_of([&] { read_stl(binary_stl(facets), "nan.stl"); });
  // Facet 1 starts at 84 + 50; its third corner 12 (normal) + 2 x 12 bytes further.
  EXPECT_TRUE(Contains(message, "nan.stl: byte offset 170: facet 1 (counting from 0) has a non-finite coordinate"));
  EXPECT_TRUE(Contains(message, "1 facet has NaN or infinite coordinates"));
}

TEST(StlReader, BinaryWithoutTrianglesContainsNoFaces) {
  EXPECT_TRUE(Contains(error_of([] { read_stl(binary_stl({}), "empty.stl"); }), "contains no faces"));
}

TEST(StlReader, ReadsAsciiWhateverTheCaseOfItsKeywords) {
  const std::string text = "solid square\n" + ascii_facet("0 0 0", "1 0 0", "1 1 0") +
                           "FACET NORMAL 0 0 1\nOUTER LOOP\nVERTEX 0 0 0\nVERTEX 1 1 0\nVERTEX 0 1 0\nENDLOOP\n"
                           "ENDFACET\nendsolid square\n";
  const PolygonSoup soup = read_stl(text, "square.stl");
  EXPECT_EQ(soup.positions.size(), 4u);
  EXPECT_EQ(soup.polygons, (std::vector<std::vector<int>>{{0, 1, 2}, {0, 2, 3}}));
}

TEST(StlReader, AsciiFacetWithFourCornersNamesTheLine) {
  const std::string text = "solid quad\n  facet normal 0 0 1\n    outer loop\n      vertex 0 0 0\n      vertex 1 0 0\n"
                           "      vertex 1 1 0\n      vertex 0 1 0\n    endloop\n  endfacet\nendsolid quad\n";
  const std::string message = error_of([&] { read_stl(text, "quad.stl"); });
  EXPECT_TRUE(Contains(message, "quad.stl: line 7: expected 'endloop'"));
}

TEST(StlReader, AsciiBadCoordinateNamesTheLine) {
  const std::string text = "solid s\n" + ascii_facet("0 0 0", "1 zero 0", "1 1 0") + "endsolid s\n";
  const std::string message = error_of([&] { read_stl(text, "bad.stl"); });
  EXPECT_TRUE(Contains(message, "bad.stl: line 5: 'zero' is not a number"));
}

TEST(StlReader, TruncatedAsciiIsRefused) {
  const std::string text = "solid s\n" + ascii_facet("0 0 0", "1 0 0", "1 1 0") + "  facet normal 0 0 1\n    outer";
  const std::string message = error_of([&] { read_stl(text, "cut.stl"); });
  EXPECT_TRUE(Contains(message, "cut.stl: line 10: expected 'outer loop'"));
  const std::string unended = "solid s\n" + ascii_facet("0 0 0", "1 0 0", "1 1 0");
  const std::string no_end = error_of([&] { read_stl(unended, "cut.stl"); });
  EXPECT_TRUE(Contains(no_end, "ends inside the solid (no 'endsolid')"));
}

}  // namespace
}  // namespace paver
