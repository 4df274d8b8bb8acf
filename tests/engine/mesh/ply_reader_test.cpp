// Tests for engine/mesh/ply_reader.cpp and ply_header.cpp: ASCII and binary PLY of either byte
// order, coordinates of any scalar type, unknown elements and properties skipped, and counts and
// list lengths checked against the file length.
#include "mesh/ply_reader.h"

#include "address_space_limit.h"
#include "byte_writer.h"
#include "input_error_assertions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace paver {
namespace {

using test::ByteWriter;
using test::Contains;
using test::error_of;

// A square whose coordinates have three different types, with an unknown vertex property, an
// unknown element holding a list, and an unknown face property after the index list.
std::string typed_ply(bool big_endian) {
  ByteWriter out(big_endian);
  out.text(std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "binary_little_endian") +
           " 1.0\ncomment written by a test\nelement vertex 4\nproperty uchar tag\nproperty double x\n"
           "property float y\nproperty short z\nelement material 1\nproperty list uchar float values\n"
           "element face 2\nproperty list uchar uint vertex_indices\nproperty int flags\nend_header\n");
  const double xs[4] = {0.1, 1.3, 1.7, 0.0};
  const float ys[4] = {0.0f, 0.0f, 1.25f, 1.0f};
  const std::int16_t zs[4] = {0, 0, 2, -1};
  for (int v = 0; v < 4; ++v) out.put(std::uint8_t(7)).put(xs[v]).put(ys[v]).put(zs[v]);
  out.put(std::uint8_t(2)).put(0.5f).put(0.25f);
  out.put(std::uint8_t(3)).put(std::uint32_t(0)).put(std::uint32_t(1)).put(std::uint32_t(2)).put(std::int32_t(-1));
  out.put(std::uint8_t(3)).put(std::uint32_t(0)).put(std::uint32_t(2)).put(std::uint32_t(3)).put(std::int32_t(5));
  return out.bytes();
}

// Little-endian float x y z and 'list uchar int vertex_indices'; `data` follows the header.
std::string float_ply_header(int vertices, int faces) {
  return "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(vertices) +
         "\nproperty float x\nproperty float y\nproperty float z\nelement face " + std::to_string(faces) +
         "\nproperty list uchar int vertex_indices\nend_header\n";
}

TEST(PlyReader, ReadsBigEndianBinary) {
  const PolygonSoup soup = read_ply(typed_ply(true), "square.ply");
  ASSERT_EQ(soup.positions.size(), 4u);
  // Coordinates keep their type's precision: the doubles exactly.
  EXPECT_EQ(soup.positions[0], glm::dvec3(0.1, 0, 0));
  EXPECT_EQ(soup.positions[1], glm::dvec3(1.3, 0, 0));
  EXPECT_EQ(soup.positions[2], glm::dvec3(1.7, 1.25, 2));
  EXPECT_EQ(soup.positions[3], glm::dvec3(0, 1, -1));
  EXPECT_EQ(soup.polygons, (std::vector<std::vector<int>>{{0, 1, 2}, {0, 2, 3}}));
}

TEST(PlyReader, BothByteOrdersReadTheSame) {
  const PolygonSoup little = read_ply(typed_ply(false), "le.ply"), big = read_ply(typed_ply(true), "be.ply");
  EXPECT_EQ(little.positions, big.positions);
  EXPECT_EQ(little.polygons, big.polygons);
}

TEST(PlyReader, AsciiSkipsUnknownElementsAndLists) {
  const std::string text =
      "ply\nformat ascii 1.0\nobj_info made by hand\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nproperty list uchar float weights\nelement material 1\nproperty list int float values\n"
      "property uchar id\nelement face 1\nproperty uchar flags\nproperty list uchar int vertex_index\nend_header\n"
      "0 0 0 2 0.5 0.5\n1 0 0 0\n0 1 0 1 9\n3 0.1 0.2 0.3 7\n5 3 0 1 2\n";
  const PolygonSoup soup = read_ply(text, "ascii.ply");
  EXPECT_EQ(soup.positions, (std::vector<glm::dvec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
  EXPECT_EQ(soup.polygons, (std::vector<std::vector<int>>{{0, 1, 2}}));
}

TEST(PlyReader, BinaryListRunningPastTheEndIsRefused) {
  ByteWriter out;
  out.text(float_ply_header(3, 1));
  for (float x : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) out.put(x);
  out.put(std::uint8_t(200)).put(0).put(1).put(2);  // 200 indices said, 3 there
  const std::string message = error_of([&] { read_ply(out.bytes(), "cut.ply"); });
  EXPECT_TRUE(Contains(message, "cut.ply: could not parse it as PLY: binary PLY size mismatch"));
  EXPECT_TRUE(Contains(message, "inside face 0 (counting from 0) of the 1 the header declares"));
  EXPECT_TRUE(Contains(message, "list 'vertex_indices'"));
  EXPECT_TRUE(Contains(message, "says it has 200 items"));
}

TEST(PlyReader, BinaryWithAbsurdCountsIsRefusedBeforeAllocating) {
  const std::string bytes = float_ply_header(50'000'000, 50'000'000) + std::string(10, '\0');
  std::string message;
  {
    const test::AddressSpaceLimit limit(256u << 20);  // an allocation for the counts fails here
    message = error_of([&] { read_ply(bytes, "absurd.ply"); });
  }
  EXPECT_TRUE(Contains(message, "binary PLY size mismatch: the header declares 50000000 vertex, 50000000 face"));
  EXPECT_TRUE(Contains(message, "but only 10 follow the header"));
}

TEST(PlyReader, ACountBeyondAnIntSaysSo) {
  // It said "expected 'element <name> <count>'", though the line was just that.
  const std::string message = error_of(
      [] { read_ply("ply\nformat ascii 1.0\nelement vertex 4000000000\nproperty float x\nend_header\n", "big.ply"); });
  EXPECT_TRUE(Contains(message, "line 3: the count 4000000000 of 'vertex' is beyond what Paver reads")) << message;
}

TEST(PlyReader, BinaryIndexOutOfRangeNamesItsOffset) {
  const std::string header = float_ply_header(3, 1);
  ByteWriter out;
  out.text(header);
  for (int i = 0; i < 9; ++i) out.put(float(i));
  out.put(std::uint8_t(3)).put(0).put(1).put(7);
  const std::string message = error_of([&] { read_ply(out.bytes(), "bad.ply"); });
  const size_t index_offset = header.size() + 36 + 1 + 8;
  EXPECT_TRUE(Contains(message, "bad.ply: byte offset " + std::to_string(index_offset) +
                                    ": face 0 (counting from 0) refers to vertex 7"));
  EXPECT_TRUE(Contains(message, "but the header declares 3 vertices (PLY indices count from 0)"));
}

TEST(PlyReader, BinaryNanNamesVertexAndOffset) {
  const std::string header = float_ply_header(3, 1);
  ByteWriter out;
  out.text(header);
  for (float x : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, std::nanf(""), 0.f}) out.put(x);
  out.put(std::uint8_t(3)).put(0).put(1).put(2);
  const std::string message = error_of([&] { read_ply(out.bytes(), "nan.ply"); });
  EXPECT_TRUE(Contains(message, "nan.ply: byte offset " + std::to_string(header.size() + 28) +
                                    ": vertex 2 (counting from 0) has a non-finite coordinate"));
  EXPECT_TRUE(Contains(message, "1 vertex has NaN or infinite coordinates"));
}

TEST(PlyReader, HeaderRefusalsNameTheLine) {
  const std::string twice = error_of([] {
    read_ply("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float x\nend_header\n", "x.ply");
  });
  EXPECT_TRUE(Contains(twice, "x.ply: could not parse it as PLY: line 5: the vertex element declares 'x' twice"));
  const std::string float_indices = error_of([] {
    read_ply("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
             "element face 1\nproperty list uchar float vertex_indices\nend_header\n",
             "f.ply");
  });
  EXPECT_TRUE(Contains(float_indices, "line 8: the face list 'vertex_indices' must hold integers"));
}

}  // namespace
}  // namespace paver
