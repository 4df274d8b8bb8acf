#include "io/element_export.h"
#include "io/coordinate_precision.h"
#include "core/interrupted.h"

#include "core/input_error.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <atomic>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

namespace paver {
namespace {

class ElementExport : public testing::Test {
protected:
  void SetUp() override {
    folder_ = std::filesystem::temp_directory_path() /
              ("paver_element_export_" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
    std::filesystem::remove_all(folder_);
    std::filesystem::create_directories(folder_);
  }
  void TearDown() override { std::filesystem::remove_all(folder_); }

  std::filesystem::path folder_;
};

std::string read_all(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// One element of every built-in shape, with awkward numbers and normals (+Z, tilted, -Z).
Elements sample_elements() {
  Elements e;
  e.push_back(ElementKind::Vertex, 0, 0, {0.1, 0.2}, {0, 0, 0}, {0, 0, 1}, 1.0, ShapeKind::Sphere);
  e.push_back(ElementKind::Edge, 3, 1, {1.0 / 3, -2e-7}, {1.25, -2.5, 3.0 / 7},
              glm::normalize(glm::dvec3(1, 2, -3)), 0.5, ShapeKind::Gem);
  e.push_back(ElementKind::Vertex, 7, 0, {12345.678, 1e-300}, {-1e5, 0.5, 2}, {0, 0, -1}, 2.0,
              ShapeKind::HexPrism);
  e.push_back(ElementKind::Edge, 9, 2, {-0.5, 0.75}, {3, 4, 5}, glm::normalize(glm::dvec3(0.3, -0.1, 0.2)),
              0.125, ShapeKind::Disc);
  return e;
}

struct Ply {
  bool doubles = false;  // x, y, z as double (a pavement float32 cannot hold: io/coordinate_precision.h)
  std::size_t header_bytes = 0;
  std::size_t vertex_count = 0;
  std::size_t face_count = 0;
  std::vector<glm::dvec3> positions;
  std::vector<std::array<std::uint8_t, 3>> colours;
  std::vector<glm::ivec3> faces;
};

// Reads back exactly the layout the writer promises (and fails the test on anything else).
Ply read_ply(const std::filesystem::path& path) {
  const std::string bytes = read_all(path);
  Ply ply;
  const std::size_t end = bytes.find("end_header\n");
  EXPECT_NE(end, std::string::npos);
  if (end == std::string::npos) return ply;
  ply.header_bytes = end + std::strlen("end_header\n");
  std::istringstream header(bytes.substr(0, ply.header_bytes));
  std::string line;
  std::getline(header, line);
  EXPECT_EQ(line, "ply");
  std::getline(header, line);
  EXPECT_EQ(line, "format binary_little_endian 1.0");
  std::vector<std::string> properties;
  while (std::getline(header, line)) {
    std::istringstream words(line);
    std::string word, element;
    words >> word;
    if (word == "element") {
      std::size_t n = 0;
      words >> element >> n;
      (element == "vertex" ? ply.vertex_count : ply.face_count) = n;
    } else if (word == "property") {
      properties.push_back(line);
    }
  }
  ply.doubles = !properties.empty() && properties[0] == "property double x";
  const std::string real = ply.doubles ? "double" : "float";
  EXPECT_EQ(properties, (std::vector<std::string>{
                            "property " + real + " x", "property " + real + " y", "property " + real + " z",
                            "property uchar red", "property uchar green", "property uchar blue",
                            "property list uchar int vertex_indices"}));
  const std::size_t coordinates = ply.doubles ? 24 : 12, stride = coordinates + 3;
  EXPECT_EQ(bytes.size(), ply.header_bytes + ply.vertex_count * stride + ply.face_count * 13);
  if (bytes.size() != ply.header_bytes + ply.vertex_count * stride + ply.face_count * 13) return ply;

  const char* p = bytes.data() + ply.header_bytes;
  for (std::size_t i = 0; i < ply.vertex_count; ++i, p += stride) {
    // The test host is little endian like the file.
    if (ply.doubles) {
      double xyz[3];
      std::memcpy(xyz, p, 24);
      ply.positions.emplace_back(xyz[0], xyz[1], xyz[2]);
    } else {
      float xyz[3];
      std::memcpy(xyz, p, 12);
      ply.positions.emplace_back(xyz[0], xyz[1], xyz[2]);
    }
    ply.colours.push_back({static_cast<std::uint8_t>(p[coordinates]), static_cast<std::uint8_t>(p[coordinates + 1]),
                           static_cast<std::uint8_t>(p[coordinates + 2])});
  }
  for (std::size_t i = 0; i < ply.face_count; ++i, p += 13) {
    EXPECT_EQ(p[0], 3);
    glm::ivec3 face;
    std::memcpy(&face[0], p + 1, 12);
    ply.faces.push_back(face);
  }
  return ply;
}

std::size_t total_vertices(const Elements& e) {
  std::size_t n = 0;
  for (ShapeKind s : e.shape) n += make_builtin_shape(s).positions.size();
  return n;
}

std::size_t total_faces(const Elements& e) {
  std::size_t n = 0;
  for (ShapeKind s : e.shape) n += make_builtin_shape(s).triangles.size();
  return n;
}

std::vector<std::string> split(const std::string& line, char separator) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(line);
  while (std::getline(in, part, separator)) parts.push_back(part);
  return parts;
}

void expect_relative(double actual, double expected) {
  EXPECT_NEAR(actual, expected, 1e-12 * std::max(1.0, std::abs(expected)));
}

TEST_F(ElementExport, PlacementsCsvRoundTrips) {
  const Elements e = sample_elements();
  const auto path = folder_ / "placements.csv";
  write_placements_csv(path, e);

  std::ifstream in(path, std::ios::binary);
  std::string line;
  ASSERT_TRUE(std::getline(in, line));
  EXPECT_EQ(line, "id,kind,x,y,z,nx,ny,nz,diameter,u,v");
  for (std::size_t i = 0; i < e.size(); ++i) {
    ASSERT_TRUE(std::getline(in, line));
    EXPECT_EQ(line.find('\r'), std::string::npos);
    const std::vector<std::string> f = split(line, ',');
    ASSERT_EQ(f.size(), 11u) << line;
    EXPECT_EQ(f[0], std::to_string(i));
    EXPECT_EQ(f[1], e.kind[i] == ElementKind::Vertex ? "V" : "E");
    const double expected[9] = {e.position[i].x, e.position[i].y, e.position[i].z,
                                e.normal[i].x,   e.normal[i].y,   e.normal[i].z,
                                e.diameter[i],   e.uv[i].x,       e.uv[i].y};
    for (int k = 0; k < 9; ++k) expect_relative(std::stod(f[2 + k]), expected[k]);
  }
  EXPECT_FALSE(std::getline(in, line));
}

TEST_F(ElementExport, PlyHasTheElementsGeometryAndDefaultColours) {
  const Elements e = sample_elements();
  const auto path = folder_ / "elements.ply";
  write_elements_ply(path, e);
  const Ply ply = read_ply(path);
  EXPECT_EQ(ply.vertex_count, total_vertices(e));
  EXPECT_EQ(ply.face_count, total_faces(e));
  ASSERT_EQ(ply.positions.size(), ply.vertex_count);
  for (const glm::ivec3& f : ply.faces)
    for (int k = 0; k < 3; ++k) {
      EXPECT_GE(f[k], 0);
      EXPECT_LT(f[k], static_cast<int>(ply.vertex_count));
    }
  std::size_t first = 0;
  for (std::size_t i = 0; i < e.size(); ++i) {
    const std::array<std::uint8_t, 3> expected =
        e.kind[i] == ElementKind::Vertex ? std::array<std::uint8_t, 3>{52, 101, 164}
                                         : std::array<std::uint8_t, 3>{237, 125, 49};
    EXPECT_EQ(ply.colours[first], expected) << "element " << i;
    first += make_builtin_shape(e.shape[i]).positions.size();
  }
  EXPECT_EQ(std::filesystem::directory_iterator(folder_)->path().filename(), "elements.ply");
}

TEST_F(ElementExport, PlyUsesGivenColours) {
  const Elements e = sample_elements();
  const std::vector<std::array<std::uint8_t, 3>> colours = {{1, 2, 3}, {4, 5, 6}, {7, 8, 9}, {10, 11, 12}};
  const auto path = folder_ / "coloured.ply";
  write_elements_ply(path, e, {.colours = &colours});
  const Ply ply = read_ply(path);
  std::size_t v = 0;
  for (std::size_t i = 0; i < e.size(); ++i)
    for (std::size_t k = 0; k < make_builtin_shape(e.shape[i]).positions.size(); ++k, ++v)
      EXPECT_EQ(ply.colours[v], colours[i]);
}

TEST_F(ElementExport, ObjHasTheSameCounts) {
  const Elements e = sample_elements();
  const auto path = folder_ / "elements.obj";
  write_elements_obj(path, e);
  std::ifstream in(path);
  std::string line;
  const std::size_t expected_vertices = total_vertices(e);
  std::size_t vertices = 0, faces = 0;
  bool named_count = false;
  while (std::getline(in, line)) {
    if (line.starts_with("# Paver elements: 4")) named_count = true;
    if (line.starts_with("v ")) {
      ++vertices;
      EXPECT_EQ(split(line, ' ').size(), 4u) << line;
    }
    if (line.starts_with("f ")) {
      ++faces;
      const std::vector<std::string> f = split(line, ' ');
      ASSERT_EQ(f.size(), 4u) << line;
      for (int k = 1; k < 4; ++k) {
        EXPECT_GE(std::stoll(f[k]), 1);
        EXPECT_LE(std::stoull(f[k]), expected_vertices);
      }
    }
  }
  EXPECT_TRUE(named_count);
  EXPECT_EQ(vertices, expected_vertices);
  EXPECT_EQ(faces, total_faces(e));
}

TEST_F(ElementExport, ObjGroupsStonesAndBeads) {
  // A CAD tool selects the beads (the metal's) apart from the stones by group.
  Elements e = sample_elements();
  e.push_back(ElementKind::Bead, -1, -1, {0, 0}, {1, 1, 1}, {0, 0, 1}, 0.3, ShapeKind::Sphere);
  e.push_back(ElementKind::Bead, -1, -1, {0, 0}, {2, 1, 1}, {0, 0, 1}, 0.3, ShapeKind::Sphere);
  write_elements_obj(folder_ / "groups.obj", e);
  std::ifstream in(folder_ / "groups.obj");
  std::vector<std::string> groups;
  std::size_t faces_before_beads = 0, faces = 0;
  for (std::string line; std::getline(in, line);) {
    if (line.starts_with("g ")) groups.push_back(line);
    if (line == "g beads") faces_before_beads = faces;
    faces += line.starts_with("f ");
  }
  EXPECT_EQ(groups, (std::vector<std::string>{"g stones", "g beads"}));
  EXPECT_EQ(faces_before_beads, total_faces(sample_elements()));
}

TEST_F(ElementExport, ObjAndPlyAgreeOnPositions) {
  const Elements e = sample_elements();
  write_elements_ply(folder_ / "a.ply", e);
  write_elements_obj(folder_ / "a.obj", e);
  const Ply ply = read_ply(folder_ / "a.ply");
  std::ifstream in(folder_ / "a.obj");
  std::string line;
  std::size_t v = 0;
  while (std::getline(in, line)) {
    if (!line.starts_with("v ")) continue;
    const std::vector<std::string> f = split(line, ' ');
    ASSERT_LT(v, ply.positions.size());
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(std::stod(f[1 + k]), ply.positions[v][k], 1e-6 * std::max(1.0, std::abs(ply.positions[v][k])));
    ++v;
  }
}

// Far from the origin for their size, elements are written in double precision (PLY and OBJ):
// in float32 a facade's discs at survey coordinates (5.4e6 m) were flattened into lines. Near the
// origin the PLY stays the float32 one every tool reads.
TEST_F(ElementExport, PlyAndObjKeepFullPrecisionWhereFloat32WouldNot) {
  Elements far = sample_elements();
  for (glm::dvec3& p : far.position) p += glm::dvec3(500000, 5400000, 120);
  ASSERT_FALSE(float32_holds(far));
  write_elements_ply(folder_ / "far.ply", far);
  write_elements_obj(folder_ / "far.obj", far);
  const Ply ply = read_ply(folder_ / "far.ply");
  EXPECT_TRUE(ply.doubles);
  ASSERT_EQ(ply.positions.size(), total_vertices(far));
  // The first element, a sphere of diameter 1 at (500000, 5400000, 120): its vertices span it.
  const std::size_t sphere = make_builtin_shape(ShapeKind::Sphere).positions.size();
  double lowest = 1e300, highest = -1e300;
  for (std::size_t k = 0; k < sphere; ++k)
    lowest = std::min(lowest, ply.positions[k].y), highest = std::max(highest, ply.positions[k].y);
  EXPECT_NEAR(highest - lowest, 1.0, 1e-6);
  std::ifstream obj(folder_ / "far.obj");
  std::string line;
  std::size_t v = 0;
  while (std::getline(obj, line) && v < ply.positions.size()) {
    if (!line.starts_with("v ")) continue;
    const std::vector<std::string> f = split(line, ' ');
    for (int k = 0; k < 3; ++k) EXPECT_EQ(std::stod(f[1 + k]), ply.positions[v][k]) << "line " << line;
    ++v;
  }
  EXPECT_EQ(v, ply.positions.size());

  Elements near = sample_elements();
  near.position[2] = glm::dvec3(-10, 0.5, 2);  // the one at -1e5 moved in
  ASSERT_TRUE(float32_holds(near));
  write_elements_ply(folder_ / "near.ply", near);
  EXPECT_FALSE(read_ply(folder_ / "near.ply").doubles);
}

TEST(CoordinatePrecision, StlWarnsFarFromTheOrigin3mfOnlyForAPieceHugeForItsElements) {
  Elements e;
  e.push_back(ElementKind::Vertex, 0, 0, {0, 0}, {0, 0, 0}, {0, 0, 1}, 0.4, ShapeKind::Disc);
  e.push_back(ElementKind::Vertex, 1, 0, {1, 0}, {12, 6, 0}, {0, 0, 1}, 0.4, ShapeKind::Disc);
  EXPECT_EQ(coordinate_rounding_warning(e, "elements.stl", "paved.3mf"), "") << "a wall near the origin";
  Elements far = e;
  for (glm::dvec3& p : far.position) p += glm::dvec3(500000, 5400000, 120);
  const std::string warning = coordinate_rounding_warning(far, "elements.stl", "paved.3mf");
  EXPECT_NE(warning.find("elements.stl holds float32 coordinates, which rounds them by up to 0.322"), std::string::npos)
      << warning;
  EXPECT_EQ(warning.find("paved.3mf"), std::string::npos) << "3MF rounds about the piece's middle: " << warning;
  EXPECT_NE(warning.find("move the model near the origin"), std::string::npos);
  // A piece 100 km across paved with 0.4 m discs: 6 digits about its middle are not enough.
  Elements huge = e;
  huge.position[1] = glm::dvec3(1e5, 0, 0);
  const std::string wide = coordinate_rounding_warning(huge, "", "paved.3mf");
  EXPECT_NE(wide.find("paved.3mf places each element with 6 significant digits"), std::string::npos) << wide;
}

// Each element's shape placed by hand: position + diameter * R(normal) * local.
TEST_F(ElementExport, ElementsAreScaledTurnedOntoTheirNormalAndMoved) {
  Elements e = sample_elements();
  e.position[2].x = -10;  // the PLY stores floats; keep them accurate enough for the volume check
  write_elements_ply(folder_ / "placed.ply", e);
  const Ply ply = read_ply(folder_ / "placed.ply");
  ASSERT_EQ(ply.positions.size(), total_vertices(e));

  std::size_t first = 0;
  for (std::size_t i = 0; i < e.size(); ++i) {
    SCOPED_TRACE("element " + std::to_string(i));
    const ShapeMesh shape = make_builtin_shape(e.shape[i]);
    const double d = e.diameter[i];
    const glm::dvec3 c = e.position[i], n = e.normal[i];
    const double tolerance = 1e-6 * std::max(1.0, glm::length(c));
    for (std::size_t k = 0; k < shape.positions.size(); ++k) {
      const glm::dvec3 local(shape.positions[k]);
      const glm::dvec3 placed = ply.positions[first + k] - c;
      // A rotation keeps the distance to the centre and maps local z onto the normal.
      EXPECT_NEAR(glm::length(placed), d * glm::length(local), tolerance);
      EXPECT_NEAR(glm::dot(placed, n), d * local.z, tolerance);
    }
    // Still outward: the signed volume about the centre is the shape's times d^3.
    double six_volume = 0, local_six_volume = 0;
    for (const glm::ivec3& t : shape.triangles) {
      six_volume += glm::dot(ply.positions[first + t.x] - c,
                             glm::cross(ply.positions[first + t.y] - c, ply.positions[first + t.z] - c));
      local_six_volume += glm::dot(glm::dvec3(shape.positions[t.x]),
                                   glm::cross(glm::dvec3(shape.positions[t.y]), glm::dvec3(shape.positions[t.z])));
    }
    EXPECT_NEAR(six_volume, local_six_volume * d * d * d, 1e-3 * std::abs(local_six_volume) * d * d * d);
    first += shape.positions.size();
  }
}

TEST_F(ElementExport, UpwardNormalKeepsTheShapeAndDownwardFlipsIt) {
  Elements e;
  e.push_back(ElementKind::Vertex, 0, 0, {0, 0}, {1, 2, 3}, {0, 0, 1}, 2.0, ShapeKind::Gem);
  e.push_back(ElementKind::Vertex, 1, 0, {0, 0}, {1, 2, 3}, {0, 0, -1}, 2.0, ShapeKind::Gem);
  write_elements_ply(folder_ / "gems.ply", e);
  const Ply ply = read_ply(folder_ / "gems.ply");
  const ShapeMesh gem = make_builtin_shape(ShapeKind::Gem);
  const std::size_t n = gem.positions.size();
  ASSERT_EQ(ply.positions.size(), 2 * n);

  double up_min = 1e9, up_max = -1e9, down_min = 1e9, down_max = -1e9;
  for (std::size_t k = 0; k < n; ++k) {
    const glm::dvec3 expected = glm::dvec3(1, 2, 3) + 2.0 * glm::dvec3(gem.positions[k]);
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(ply.positions[k][a], expected[a], 1e-6);
    // Flipped: z mirrored about the centre.
    EXPECT_NEAR(ply.positions[n + k].z, 3 - 2.0 * gem.positions[k].z, 1e-6);
    up_min = std::min(up_min, ply.positions[k].z);
    up_max = std::max(up_max, ply.positions[k].z);
    down_min = std::min(down_min, ply.positions[n + k].z);
    down_max = std::max(down_max, ply.positions[n + k].z);
  }
  // Upright the culet points down; flipped it points up.
  EXPECT_GT(3 - up_min, up_max - 3);
  EXPECT_GT(down_max - 3, 3 - down_min);
}

TEST_F(ElementExport, CustomShapeIsUsedAndRequired) {
  Elements e;
  e.push_back(ElementKind::Vertex, 0, 0, {0, 0}, {0, 0, 0}, {0, 0, 1}, 1.0, ShapeKind::Custom);
  e.push_back(ElementKind::Edge, 0, 0, {0, 0}, {2, 0, 0}, {0, 1, 0}, 1.0, ShapeKind::Sphere);

  const auto path = folder_ / "custom.ply";
  EXPECT_THROW(write_elements_ply(path, e), InputError);
  EXPECT_THROW(write_elements_obj(folder_ / "custom.obj", e), InputError);
  EXPECT_TRUE(std::filesystem::is_empty(folder_)) << "nothing is written when the shape is missing";

  ShapeMesh tetra;
  tetra.positions = {{0.5f, 0, -0.2f}, {-0.5f, 0.3f, -0.2f}, {-0.5f, -0.3f, -0.2f}, {0, 0, 0.4f}};
  tetra.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
  write_elements_ply(path, e, {.custom = &tetra});
  const Ply ply = read_ply(path);
  const ShapeMesh sphere = make_builtin_shape(ShapeKind::Sphere);
  EXPECT_EQ(ply.vertex_count, 4 + sphere.positions.size());
  EXPECT_EQ(ply.face_count, 4 + sphere.triangles.size());
  EXPECT_NEAR(ply.positions[3].z, 0.4, 1e-6);
}

TEST_F(ElementExport, StlHasEveryShapeTriangleAndTheBinaryLayout) {
  const Elements e = sample_elements();
  const auto path = folder_ / "elements.stl";
  write_elements_stl(path, e);
  const std::string bytes = read_all(path);
  const std::size_t triangles = total_faces(e);
  ASSERT_EQ(bytes.size(), 84 + 50 * triangles);
  EXPECT_FALSE(bytes.starts_with("solid")) << "an ASCII STL reader would take it for text";
  std::uint32_t count = 0;
  std::memcpy(&count, bytes.data() + 80, 4);
  EXPECT_EQ(count, triangles);

  // The vertices are the PLY's (same transform), and each normal is the unit face normal.
  write_elements_ply(folder_ / "same.ply", e);
  const Ply ply = read_ply(folder_ / "same.ply");
  ASSERT_EQ(ply.faces.size(), triangles);
  for (std::size_t f = 0; f < triangles; ++f) {
    float v[12];
    std::memcpy(v, bytes.data() + 84 + 50 * f, sizeof v);
    for (int corner = 0; corner < 3; ++corner)
      for (int k = 0; k < 3; ++k)
        ASSERT_EQ(v[3 + 3 * corner + k], float(ply.positions[ply.faces[f][corner]][k])) << "triangle " << f;
    const glm::dvec3 a(v[3], v[4], v[5]), b(v[6], v[7], v[8]), c(v[9], v[10], v[11]);
    const glm::dvec3 cross = glm::cross(b - a, c - a);
    if (glm::length(cross) < 1e-9) continue;  // float rounding makes slivers' normals arbitrary
    EXPECT_NEAR(glm::dot(glm::dvec3(v[0], v[1], v[2]), glm::normalize(cross)), 1.0, 1e-3) << "triangle " << f;
  }
}

TEST_F(ElementExport, StlTriangleCountIsTheSumOfTheShapes) {
  Elements e;
  for (int i = 0; i < 10; ++i)
    e.push_back(ElementKind::Vertex, i, 0, {0, 0}, {double(i), 0, 0}, {0, 0, 1}, 0.5, ShapeKind(i % 4));
  write_elements_stl(folder_ / "ten.stl", e);
  const std::string bytes = read_all(folder_ / "ten.stl");
  std::size_t triangles = 0;
  for (int i = 0; i < 10; ++i) triangles += make_builtin_shape(ShapeKind(i % 4)).triangles.size();
  EXPECT_EQ(bytes.size(), 84 + 50 * triangles);
  EXPECT_THROW(write_elements_stl(folder_ / "no" / "ten.stl", e), InputError);
}

TEST_F(ElementExport, NoElementsGiveValidEmptyFiles) {
  const Elements e;
  write_placements_csv(folder_ / "empty.csv", e);
  write_elements_ply(folder_ / "empty.ply", e);
  write_elements_obj(folder_ / "empty.obj", e);
  write_elements_stl(folder_ / "empty.stl", e);
  EXPECT_EQ(read_all(folder_ / "empty.csv"), "id,kind,x,y,z,nx,ny,nz,diameter,u,v\n");
  EXPECT_EQ(read_all(folder_ / "empty.stl").size(), 84u);
  const Ply ply = read_ply(folder_ / "empty.ply");
  EXPECT_EQ(ply.vertex_count, 0u);
  EXPECT_EQ(ply.face_count, 0u);
}

TEST_F(ElementExport, MissingFolderThrowsInputError) {
  const Elements e = sample_elements();
  EXPECT_THROW(write_placements_csv(folder_ / "no" / "placements.csv", e), InputError);
  EXPECT_THROW(write_elements_ply(folder_ / "no" / "elements.ply", e), InputError);
  EXPECT_TRUE(std::filesystem::is_empty(folder_));
}

// A stop request ends a large export within a chunk (Ctrl-C during export once left
// `.NAME.tmp.PID.N` files): each writer throws Interrupted and leaves no file at all.
TEST_F(ElementExport, AStopEndsEveryWriterAndLeavesNoFile) {
  Elements many;
  for (int i = 0; i < 20000; ++i)  // a few MiB in every format: past the first flush
    many.push_back(ElementKind::Vertex, i, 0, {i, 0}, {i, 0, 0}, {0, 0, 1}, 1.0, ShapeKind::Sphere);
  const std::atomic<bool> stop{true};
  ElementMeshOptions options;
  options.stop = &stop;
  EXPECT_THROW(write_placements_csv(folder_ / "placements.csv", many, &stop), Interrupted);
  EXPECT_THROW(write_elements_ply(folder_ / "elements.ply", many, options), Interrupted);
  EXPECT_THROW(write_elements_obj(folder_ / "elements.obj", many, options), Interrupted);
  EXPECT_THROW(write_elements_stl(folder_ / "elements.stl", many, options), Interrupted);
  EXPECT_TRUE(std::filesystem::is_empty(folder_)) << "a stopped writer left a file";

  // Without a request the same writers finish.
  const std::atomic<bool> go{false};
  options.stop = &go;
  write_elements_ply(folder_ / "elements.ply", many, options);
  EXPECT_GT(std::filesystem::file_size(folder_ / "elements.ply"), std::size_t(1) << 20);
}

}  // namespace
}  // namespace paver
