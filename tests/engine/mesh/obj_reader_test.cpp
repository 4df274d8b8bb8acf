// Tests for engine/mesh/obj_reader.cpp beyond what the loader's tests cover: what the soup holds
// (double-precision positions, corners in file order, repeated corners) and forward references.
#include "mesh/obj_reader.h"

#include "input_error_assertions.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace paver {
namespace {

using test::Contains;
using test::error_of;

// Survey coordinates keep their centimetres: read in single precision, 5400000.3 became 5400000.5,
// welding a facade's vertices and flattening its discs.
TEST(ObjReader, PositionsAreDoublePrecision) {
  const PolygonSoup soup = read_obj("v 0.1 1e-50 -2.5\nv 500000.3 5400000.3 120.01\nv 0 1 0\nf 1 2 3\n", "p.obj");
  EXPECT_EQ(soup.positions[0], glm::dvec3(0.1, 1e-50, -2.5));
  EXPECT_EQ(soup.positions[1], glm::dvec3(500000.3, 5400000.3, 120.01));
  // Past double's range a value is infinite: refused like any non-finite coordinate.
  const std::string message = error_of([] { read_obj("v 1e400 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "big.obj"); });
  EXPECT_TRUE(Contains(message, "big.obj: line 1: vertex 1 (counting from 1) has a non-finite coordinate '1e400'")) << message;
}

TEST(ObjReader, RepeatedCornersKeepTheFirst) {
  // 'f 1 2 3 2' is the triangle 1 2 3; 'f 1 1 2' collapses and is only counted.
  const PolygonSoup soup = read_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3 2\nf 1 1 2\n", "r.obj");
  EXPECT_EQ(soup.polygons, (std::vector<std::vector<int>>{{0, 1, 2}}));
  EXPECT_EQ(soup.collapsed_faces, 1);
}

TEST(ObjReader, AByteOrderMarkIsSkipped) {
  // It hid the first vertex ("refers to vertex 3 but the file defines only 2").
  const PolygonSoup soup = read_obj("\xEF\xBB\xBFv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "bom.obj");
  EXPECT_EQ(soup.positions.size(), 3u);
  EXPECT_EQ(soup.polygons, (std::vector<std::vector<int>>{{0, 1, 2}}));
}

TEST(ObjReader, FacesMayReferToVerticesDefinedLater) {
  const PolygonSoup soup = read_obj("f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n", "later.obj");
  EXPECT_EQ(soup.polygons, (std::vector<std::vector<int>>{{0, 1, 2}}));
  const std::string message = error_of([] { read_obj("f 1 2 4\nv 0 0 0\nv 1 0 0\nv 0 1 0\n", "bad.obj"); });
  EXPECT_TRUE(Contains(message, "bad.obj: line 1: the face refers to vertex 4 but the file defines only 3 vertices"));
  const std::string huge = error_of([] { read_obj("v 0 0 0\nv 1 0 0\nf 1 2 9999999999\n", "huge.obj"); });
  EXPECT_TRUE(Contains(huge, "huge.obj: line 3: the face refers to vertex 9999999999"));
}

}  // namespace
}  // namespace paver
