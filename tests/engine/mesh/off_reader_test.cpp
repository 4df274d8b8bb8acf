// Tests for engine/mesh/off_reader.cpp: text and binary OFF ("OFF BINARY" as OpenMesh wrote it),
// and binary counts checked against the file length before anything is allocated.
#include "mesh/off_reader.h"

#include "address_space_limit.h"
#include "byte_writer.h"
#include "input_error_assertions.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

namespace paver {
namespace {

using test::ByteWriter;
using test::Contains;
using test::error_of;

// A binary OFF with the counts given (whatever the data) and the vertices and faces given.
std::string binary_off(std::uint32_t vertex_count, std::uint32_t face_count, const std::vector<glm::vec3>& vertices,
                       const std::vector<std::vector<std::uint32_t>>& faces, const char* header = "OFF BINARY\n",
                       bool big_endian = false) {
  ByteWriter out(big_endian);
  out.text(header).put(vertex_count).put(face_count).put(std::uint32_t(0));
  for (const glm::vec3& v : vertices) out.put(v.x).put(v.y).put(v.z);
  for (const auto& face : faces) {
    out.put(std::uint32_t(face.size()));
    for (std::uint32_t index : face) out.put(index);
  }
  return out.bytes();
}

const std::vector<glm::vec3> kSquare = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};

TEST(OffReader, ReadsBinary) {
  const PolygonSoup soup = read_off(binary_off(4, 2, kSquare, {{0, 1, 2}, {0, 2, 3}}), "square.off");
  ASSERT_EQ(soup.positions.size(), 4u);
  EXPECT_EQ(soup.positions[2], glm::dvec3(1, 1, 0));
  EXPECT_EQ(soup.polygons, (std::vector<std::vector<int>>{{0, 1, 2}, {0, 2, 3}}));
}

// Geomview's binary OFF is big-endian, OpenMesh's little-endian: both read the same.
TEST(OffReader, ReadsBinaryInEitherByteOrder) {
  const auto faces = std::vector<std::vector<std::uint32_t>>{{0, 1, 2}, {0, 2, 3}};
  const PolygonSoup little = read_off(binary_off(4, 2, kSquare, faces), "le.off");
  const PolygonSoup big = read_off(binary_off(4, 2, kSquare, faces, "OFF BINARY\n", true), "be.off");
  EXPECT_EQ(big.positions, little.positions);
  EXPECT_EQ(big.polygons, little.polygons);
  // A truncated big-endian file is still refused, with its counts as little-endian would read them.
  std::string cut = binary_off(4, 2, kSquare, faces, "OFF BINARY\n", true);
  cut.resize(cut.size() - 6);
  EXPECT_THROW(read_off(cut, "cut.off"), InputError);
}

TEST(OffReader, ReadsBinaryWithNormals) {
  ByteWriter out;
  out.text("NOFF BINARY\n").put(std::uint32_t(3)).put(std::uint32_t(1)).put(std::uint32_t(0));
  for (const glm::vec3& v : {glm::vec3(0, 0, 0), glm::vec3(2, 0, 0), glm::vec3(0, 2, 0)})
    out.put(v.x).put(v.y).put(v.z).put(0.0f).put(0.0f).put(1.0f);
  out.put(std::uint32_t(3)).put(std::uint32_t(0)).put(std::uint32_t(1)).put(std::uint32_t(2));
  const PolygonSoup soup = read_off(out.bytes(), "normals.off");
  ASSERT_EQ(soup.positions.size(), 3u);
  EXPECT_EQ(soup.positions[1], glm::dvec3(2, 0, 0));
  EXPECT_EQ(soup.polygons, (std::vector<std::vector<int>>{{0, 1, 2}}));
}

TEST(OffReader, TruncatedBinaryIsRefused) {
  const std::string whole = binary_off(4, 1, kSquare, {{0, 1, 2, 3}});
  // Cut inside the vertices: less than the counts need at the very least.
  const std::string early = error_of([&] { read_off(whole.substr(0, 40), "cut.off"); });
  EXPECT_TRUE(Contains(early, "cut.off: byte offset 11: the counts declare 4 vertices and 1 face"));
  EXPECT_TRUE(Contains(early, "truncated"));
  // Cut inside the quad's indices: the minimum (a triangle) is there, the quad is not.
  const std::string late = error_of([&] { read_off(whole.substr(0, whole.size() - 2), "cut.off"); });
  EXPECT_TRUE(Contains(late, "cut.off: byte offset 71: face 0 (counting from 0) says it has 4 vertices"));
}

TEST(OffReader, BinaryWithAbsurdCountsIsRefusedBeforeAllocating) {
  // 50 million vertices and faces would take gigabytes; the file has 100 bytes.
  std::string bytes = binary_off(50'000'000, 50'000'000, {}, {});  // 23 bytes
  bytes += std::string(77, '\0');
  const auto start = std::chrono::steady_clock::now();
  std::string message;
  {
    const test::AddressSpaceLimit limit(256u << 20);  // an allocation for the counts fails here
    message = error_of([&] { read_off(bytes, "absurd.off"); });
  }
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(2));
  EXPECT_TRUE(Contains(message, "absurd.off: byte offset 11: the counts declare 50000000 vertices and 50000000 faces"));
  EXPECT_TRUE(Contains(message, "only 77 follow them"));
  // Counts at the 32-bit limit do not overflow the size check.
  const std::string largest = error_of([] { read_off(binary_off(0xffffffffu, 0xffffffffu, {}, {}), "max.off"); });
  EXPECT_TRUE(Contains(largest, "declare 4294967295 vertices and 4294967295 faces"));
}

TEST(OffReader, BinaryFaceIndexOutOfRangeNamesItsOffset) {
  const std::string message = error_of([] { read_off(binary_off(4, 1, kSquare, {{0, 1, 9}}), "bad.off"); });
  EXPECT_TRUE(Contains(message, "bad.off: byte offset 83: face 0 (counting from 0): vertex index 9 is out of range"));
}

TEST(OffReader, BinaryFaceWithTwoCornersIsRefused) {
  const std::string message = error_of([] { read_off(binary_off(4, 2, kSquare, {{0, 1}, {0, 1, 2, 3}}), "bad.off"); });
  EXPECT_TRUE(Contains(message, "byte offset 71: face 0 (counting from 0) has 2 vertices; a face needs at least 3"));
}

TEST(OffReader, BinaryBytesAfterTheLastFaceAreRefused) {
  const std::string bytes = binary_off(4, 1, kSquare, {{0, 1, 2}, {0, 2, 3}});  // counts say 1 face
  const std::string message = error_of([&] { read_off(bytes, "long.off"); });
  EXPECT_TRUE(Contains(message, "long.off: byte offset 87: 16 bytes follow the last face"));
}

TEST(OffReader, TextWithNormalsAndColours) {
  const PolygonSoup normals = read_off("NOFF\n3 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n", "n.off");
  EXPECT_EQ(normals.positions[1], glm::dvec3(1, 0, 0));
  const PolygonSoup colours =
      read_off("COFF\n3 1 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n3 0 1 2 9 9 9\n", "c.off");
  EXPECT_EQ(colours.polygons, (std::vector<std::vector<int>>{{0, 1, 2}}));
}

}  // namespace
}  // namespace paver
