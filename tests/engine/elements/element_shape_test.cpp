#include "elements/element_shape.h"

#include "core/input_error.h"
#include "mesh/mesh_loader.h"

#include "input_error_assertions.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <utility>

namespace paver {
namespace {

constexpr ShapeKind kBuiltins[] = {ShapeKind::Sphere, ShapeKind::Gem, ShapeKind::HexPrism,
                                   ShapeKind::Disc};

struct Box {
  glm::dvec3 lo{1e300}, hi{-1e300};
};

Box bounds(const ShapeMesh& mesh) {
  Box box;
  for (const glm::vec3& p : mesh.positions) {
    box.lo = glm::min(box.lo, glm::dvec3(p));
    box.hi = glm::max(box.hi, glm::dvec3(p));
  }
  return box;
}

double signed_volume(const ShapeMesh& mesh) {
  double six_volume = 0;
  for (const glm::ivec3& t : mesh.triangles)
    six_volume += glm::dot(glm::dvec3(mesh.positions[t.x]),
                           glm::cross(glm::dvec3(mesh.positions[t.y]), glm::dvec3(mesh.positions[t.z])));
  return six_volume / 6;
}

// Closed and consistently oriented: every directed edge appears once and its reverse once.
void expect_closed(const ShapeMesh& mesh) {
  std::map<std::pair<int, int>, int> directed;
  const int n = static_cast<int>(mesh.positions.size());
  for (const glm::ivec3& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      ASSERT_GE(t[k], 0);
      ASSERT_LT(t[k], n);
      ++directed[{t[k], t[(k + 1) % 3]}];
    }
  }
  for (const auto& [edge, uses] : directed) {
    EXPECT_EQ(uses, 1) << "edge " << edge.first << "-" << edge.second << " used " << uses << " times";
    const auto reverse = directed.find({edge.second, edge.first});
    EXPECT_TRUE(reverse != directed.end() && reverse->second == 1)
        << "edge " << edge.first << "-" << edge.second << " has no single opposite";
  }
}

class TempFolder {
public:
  TempFolder() {
    const auto* info = testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() /
            ("paver_" + std::string(info->test_suite_name()) + "_" + info->name());
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempFolder() { std::filesystem::remove_all(path_); }
  std::filesystem::path file(const std::string& name) const { return path_ / name; }

private:
  std::filesystem::path path_;
};

void write(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

TEST(ElementShape, BuiltinShapesAreClosedAndFaceOutwards) {
  for (ShapeKind kind : kBuiltins) {
    SCOPED_TRACE(std::string(enum_name(kind)));
    const ShapeMesh mesh = make_builtin_shape(kind);
    ASSERT_FALSE(mesh.triangles.empty());
    expect_closed(mesh);
    EXPECT_GT(signed_volume(mesh), 0);
    // Euler characteristic of a sphere-like closed surface: V - E + F = 2 with E = 3F / 2.
    EXPECT_EQ(2 * static_cast<long>(mesh.positions.size()) - static_cast<long>(mesh.triangles.size()), 4);
    for (const glm::ivec3& t : mesh.triangles) {
      const glm::dvec3 a(mesh.positions[t.x]), b(mesh.positions[t.y]), c(mesh.positions[t.z]);
      EXPECT_GT(glm::length(glm::cross(b - a, c - a)), 1e-6) << "degenerate triangle";
    }
  }
}

TEST(ElementShape, BuiltinShapesHaveUnitDiameterAndAreCentred) {
  for (ShapeKind kind : kBuiltins) {
    SCOPED_TRACE(std::string(enum_name(kind)));
    const Box box = bounds(make_builtin_shape(kind));
    EXPECT_NEAR(std::max(box.hi.x - box.lo.x, box.hi.y - box.lo.y), 1.0, 1e-6);
    EXPECT_NEAR(box.lo.x + box.hi.x, 0.0, 1e-6);
    EXPECT_NEAR(box.lo.y + box.hi.y, 0.0, 1e-6);
    // The gem sits on its girdle (z = 0), the others on their middle.
    if (kind != ShapeKind::Gem) {
      EXPECT_NEAR(box.lo.z + box.hi.z, 0.0, 1e-6);
    }
  }
}

TEST(ElementShape, BuiltinShapesHaveTheirSizes) {
  const ShapeMesh sphere = make_builtin_shape(ShapeKind::Sphere);
  EXPECT_LE(sphere.triangles.size(), 400u);  // a pavement can have 100k of them
  for (const glm::vec3& p : sphere.positions) EXPECT_NEAR(glm::length(glm::dvec3(p)), 0.5, 1e-6);

  const Box hex = bounds(make_builtin_shape(ShapeKind::HexPrism));
  EXPECT_NEAR(hex.hi.z - hex.lo.z, 0.5, 1e-6);
  EXPECT_NEAR(hex.hi.y - hex.lo.y, std::sqrt(3.0) / 2, 1e-6);  // across the flats
  EXPECT_EQ(make_builtin_shape(ShapeKind::HexPrism).positions.size(), 14u);

  const ShapeMesh disc = make_builtin_shape(ShapeKind::Disc);
  const Box disc_box = bounds(disc);
  EXPECT_NEAR(disc_box.lo.z, -0.1, 1e-6);
  EXPECT_NEAR(disc_box.hi.z, 0.1, 1e-6);
  EXPECT_EQ(disc.triangles.size(), 4u * 32u);
}

TEST(ElementShape, GemHasTableAboveGirdleAndCuletAtTheBottom) {
  const ShapeMesh gem = make_builtin_shape(ShapeKind::Gem);
  const Box box = bounds(gem);

  // Girdle: the widest vertices, a thin band around z = 0.
  int girdle = 0;
  for (const glm::vec3& p : gem.positions) {
    if (std::hypot(p.x, p.y) > 0.5 - 1e-6) {
      ++girdle;
      EXPECT_LE(std::abs(p.z), 0.0100001);
    }
  }
  EXPECT_EQ(girdle, 32);

  // Table: a flat top, well inside the girdle, about 0.56 across; crown about 0.16 high.
  int table = 0;
  double table_radius = 0;
  for (const glm::vec3& p : gem.positions) {
    if (p.z > box.hi.z - 1e-6) {
      ++table;
      table_radius = std::max(table_radius, std::hypot(double(p.x), double(p.y)));
    }
  }
  EXPECT_GE(table, 8);
  EXPECT_NEAR(2 * table_radius, 0.56, 0.03);
  EXPECT_NEAR(box.hi.z, 0.17, 0.02);

  // Culet: one point on the axis at the lowest z, about 0.43 below the girdle.
  int lowest = 0;
  for (const glm::vec3& p : gem.positions) {
    if (p.z < box.lo.z + 1e-6) {
      ++lowest;
      EXPECT_NEAR(p.x, 0, 1e-6);
      EXPECT_NEAR(p.y, 0, 1e-6);
    }
  }
  EXPECT_EQ(lowest, 1);
  EXPECT_NEAR(box.lo.z, -0.44, 0.02);
}

TEST(ElementShape, NamesRoundTrip) {
  for (ShapeKind kind : {ShapeKind::Sphere, ShapeKind::Gem, ShapeKind::HexPrism, ShapeKind::Disc,
                         ShapeKind::Custom})
    EXPECT_EQ(enum_from_name<ShapeKind>(enum_name(kind)), kind);
  EXPECT_EQ(enum_name(ShapeKind::HexPrism), "hex_prism");
  EXPECT_EQ(enum_from_name<ShapeKind>("cube"), std::nullopt);
  EXPECT_EQ(enum_from_name<ShapeKind>(""), std::nullopt);
}

TEST(ElementShape, CustomIsNotBuiltIn) {
  EXPECT_THROW(make_builtin_shape(ShapeKind::Custom), InputError);
}

TEST(ElementShape, LoadCustomShapeNormalisesAndTriangulates) {
  const TempFolder folder;
  const auto path = folder.file("box.obj");
  // A 4 x 2 x 1 box with quad faces, away from the origin, plus an unused far-away vertex.
  write(path,
        "v 2 3 4\nv 6 3 4\nv 6 5 4\nv 2 5 4\nv 2 3 5\nv 6 3 5\nv 6 5 5\nv 2 5 5\nv 100 100 100\n"
        "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n");
  const ShapeMesh shape = load_custom_shape(path);
  EXPECT_EQ(shape.triangles.size(), 12u);
  EXPECT_EQ(shape.positions.size(), 8u);
  // Scaled so that its outline fits the unit disc: the 4 x 2 footprint's corners reach
  // sqrt(2^2 + 1^2) = sqrt(5) from its centre, which becomes 0.5.
  const Box box = bounds(shape);
  const double scale = 0.5 / std::sqrt(5.0);
  EXPECT_NEAR(box.hi.x - box.lo.x, 4 * scale, 1e-6);
  EXPECT_NEAR(box.hi.y - box.lo.y, 2 * scale, 1e-6);
  EXPECT_NEAR(box.hi.z - box.lo.z, 1 * scale, 1e-6);
  float reach = 0;
  for (const glm::vec3& p : shape.positions) reach = std::max(reach, std::sqrt(p.x * p.x + p.y * p.y));
  EXPECT_NEAR(reach, 0.5, 1e-6) << "the footprint touches the element's disc, inside it";
  for (int axis = 0; axis < 3; ++axis) EXPECT_NEAR(box.lo[axis] + box.hi[axis], 0.0, 1e-6);
  expect_closed(shape);
  EXPECT_GT(signed_volume(shape), 0);
}

// A shape drawn standing on z = 0 (a boss, a cone on its base) keeps that plane as the surface:
// bounding-box centring sank the bundled boss half into the mould (3.5 mm of its 5.4 mm).
TEST(ElementShape, LoadCustomShapeKeepsZeroHeightAsTheSurface) {
  const TempFolder folder;
  const auto path = folder.file("cone.obj");
  // A square pyramid 4 wide and 2 high, base on z = 0.
  write(path, "v -2 -2 0\nv 2 -2 0\nv 2 2 0\nv -2 2 0\nv 0 0 2\nf 1 4 3 2\nf 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\n");
  const Box box = bounds(load_custom_shape(path));
  const double scale = 0.5 / std::sqrt(8.0);  // the corners reach 2 sqrt(2)
  EXPECT_NEAR(box.lo.z, 0.0, 1e-7) << "its base is on the surface";
  EXPECT_NEAR(box.hi.z, 2 * scale, 1e-6);
  EXPECT_NEAR(box.lo.x + box.hi.x, 0.0, 1e-6);
  // The bundled boss is drawn 0.15 into the surface and 0.5 out of it, at unit diameter.
  const Box boss = bounds(load_custom_shape(test::source_dir() / "assets/shapes/boss.obj"));
  EXPECT_NEAR(boss.lo.z, -0.15, 1e-5);
  EXPECT_NEAR(boss.hi.z, 0.5, 1e-5);
}

TEST(ElementShape, LoadCustomShapeRejectsBadFiles) {
  const TempFolder folder;
  // The message names the file and says what is wrong with it.
  const auto expect_error = [](const std::filesystem::path& path, const std::string& reason) {
    try {
      load_custom_shape(path);
      ADD_FAILURE() << "no error for " << path;
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find(path.string()), std::string::npos) << message;
      EXPECT_NE(message.find(reason), std::string::npos) << message;
    }
  };
  expect_error(folder.file("missing.obj"), "not found");

  const auto empty = folder.file("empty.obj");
  write(empty, "# nothing here\n");
  expect_error(empty, "no faces");

  const auto points = folder.file("points.obj");
  write(points, "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
  expect_error(points, "no faces");

  const auto unknown = folder.file("shape.xyz");
  write(unknown, "0 0 0\n");
  expect_error(unknown, "unsupported file type");

  // Binary PLY with one triangle, one corner NaN: refused by the reader.
  const auto nan_ply = folder.file("nan.ply");
  {
    std::ofstream out(nan_ply, std::ios::binary);
    out << "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
           "property float y\nproperty float z\nelement face 1\n"
           "property list uchar int vertex_indices\nend_header\n";
    const float xyz[9] = {0, 0, 0, 1, 0, 0, std::nanf(""), 1, 0};
    out.write(reinterpret_cast<const char*>(xyz), sizeof xyz);  // the test host is little endian
    const std::uint8_t corners = 3;
    const std::int32_t face[3] = {0, 1, 2};
    out.write(reinterpret_cast<const char*>(&corners), 1);
    out.write(reinterpret_cast<const char*>(face), sizeof face);
  }
  expect_error(nan_ply, "non-finite");

  const auto vertical = folder.file("vertical.obj");
  write(vertical, "v 0 0 0\nv 0 0 1\nv 0 0 2\nf 1 2 3\n");
  expect_error(vertical, "no horizontal extent");
}

TEST(ElementShape, BadCustomShapeIsRefusedWithTheSurfaceLoadersMessage) {
  // The same readers as surfaces: the same message, after "custom shape ".
  const TempFolder folder;
  const auto bad_obj = folder.file("bad.obj");
  write(bad_obj, "v 0 0 0\nv 1 x 0\nv 0 1 0\nf 1 2 3\n");
  const auto cut_stl = folder.file("cut.stl");
  write(cut_stl, std::string(80, ' ') + std::string("\x02\0\0\0", 4) + std::string(60, '\0'));
  // A corrupt binary PLY whose counts claim 50 million vertices and faces in 10 bytes (such a
  // shape once hung the run with growing memory): refused from the file's length, at once.
  const auto absurd_ply = folder.file("absurd.ply");
  write(absurd_ply, "ply\nformat binary_little_endian 1.0\nelement vertex 50000000\nproperty float x\n"
                    "property float y\nproperty float z\nelement face 50000000\n"
                    "property list uchar int vertex_indices\nend_header\n" + std::string(10, '\0'));
  for (const auto& path : {bad_obj, cut_stl, absurd_ply}) {
    const std::string shape = test::error_of([&] { load_custom_shape(path); });
    const std::string surface = test::error_of([&] { load_surface(path); });
    EXPECT_EQ(shape, "custom shape " + surface);
  }
  EXPECT_EQ(test::error_of([&] { load_custom_shape(bad_obj); }),
            "custom shape " + bad_obj.string() +
                ": line 2: 'x' is not a number; vertex coordinates must be numbers");
}

}  // namespace
}  // namespace paver

namespace paver {
namespace {

// Unit wide along x and closed (every directed edge has its reverse).
void expect_unit_wide_and_closed(const ShapeMesh& shape, const std::string& what) {
  float lo = 1e9f, hi = -1e9f;
  for (const auto& p : shape.positions) lo = std::min(lo, p.x), hi = std::max(hi, p.x);
  EXPECT_NEAR(hi - lo, 1.0f, 1e-6f) << what;
  std::set<std::pair<int, int>> edges;
  for (const auto& t : shape.triangles) edges.insert({t.x, t.y}), edges.insert({t.y, t.z}), edges.insert({t.z, t.x});
  for (const auto& [a, b] : edges) EXPECT_TRUE(edges.count({b, a})) << what;
}

TEST(ElementShape, CoarseShapesAreLighterButStillUnitWideAndClosed) {
  for (ShapeKind kind : {ShapeKind::Sphere, ShapeKind::Disc}) {
    const ShapeMesh full = make_builtin_shape(kind), coarse = make_builtin_shape(kind, ShapeDetail::Coarse);
    EXPECT_LT(coarse.triangles.size() * 2, full.triangles.size()) << enum_name(kind);
    expect_unit_wide_and_closed(coarse, std::string(enum_name(kind)));
  }
}

TEST(ElementShape, MinimalShapesAreLighterStillButUnitWideAndClosed) {
  // What the 3D view draws for tens of thousands of elements, at most half of Coarse: a sphere of
  // 12 triangles, a gem of 32.
  for (ShapeKind kind : {ShapeKind::Sphere, ShapeKind::Gem, ShapeKind::Disc}) {
    const ShapeMesh coarse = make_builtin_shape(kind, ShapeDetail::Coarse);
    const ShapeMesh minimal = make_builtin_shape(kind, ShapeDetail::Minimal);
    EXPECT_LE(minimal.triangles.size() * 2, coarse.triangles.size()) << enum_name(kind);
    expect_unit_wide_and_closed(minimal, std::string(enum_name(kind)) + " minimal");
  }
  EXPECT_EQ(make_builtin_shape(ShapeKind::Sphere, ShapeDetail::Minimal).triangles.size(), 12u);
  // The gem keeps its flat table on top (+Z) and its culet below, at the brilliant's heights.
  const ShapeMesh gem = make_builtin_shape(ShapeKind::Gem, ShapeDetail::Minimal);
  float top = -1e9f, bottom = 1e9f;
  for (const auto& p : gem.positions) top = std::max(top, p.z), bottom = std::min(bottom, p.z);
  EXPECT_NEAR(top, kGemGirdleHalf + kGemCrownHeight, 1e-6);
  EXPECT_NEAR(top - bottom, kGemDepth, 1e-6);
}

}  // namespace
}  // namespace paver

namespace paver {
namespace {

// The contact rule takes each element's footprint as the disc of its diameter: every built-in
// shape's outline along +Z must fit the unit disc, and fill it (else the rule would be loose).
TEST(ElementShape, BuiltInFootprintsFitTheUnitDisc) {
  for (ShapeKind kind : {ShapeKind::Sphere, ShapeKind::Gem, ShapeKind::HexPrism, ShapeKind::Disc})
    for (ShapeDetail detail : {ShapeDetail::Full, ShapeDetail::Coarse, ShapeDetail::Minimal}) {
      const ShapeMesh shape = make_builtin_shape(kind, detail);
      float reach = 0;
      for (const glm::vec3& p : shape.positions) reach = std::max(reach, std::sqrt(p.x * p.x + p.y * p.y));
      EXPECT_LE(reach, 0.5f + 1e-6f) << enum_name(kind);
      EXPECT_GE(reach, 0.49f) << enum_name(kind);
    }
}

}  // namespace
}  // namespace paver
