// Tests for engine/mesh/mesh_loader.cpp (and surface_mesh.cpp): every refusal names the file and
// the problem, every repair is reported, and the real meshes load with their known counts.
#include "core/input_error.h"
#include "mesh/mesh_loader.h"
#include "mesh/surface_mesh.h"

#include "input_error_assertions.h"

#include "temp_folder.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <array>

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <numbers>
#include <random>
#include <set>
#include <sstream>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace paver {
namespace {

using test::Contains;
using test::error_of;

namespace fs = std::filesystem;

class MeshLoaderTest : public test::TempFolderTest {};

// The InputError message `load` throws, or a test failure if it throws none.
std::string load_error(const fs::path& path) {
  return error_of([&] { load_surface(path); });
}

bool any_warning_contains(const LoadedSurface& loaded, const std::string& part) {
  for (const std::string& warning : loaded.warnings)
    if (warning.find(part) != std::string::npos) return true;
  return false;
}

// A facade in survey coordinates keeps its centimetres (read in float32 its vertices, 0.3 m
// apart, welded and its area changed); a surface near the origin is rounded to float32 as Paver
// always read it, so earlier results repeat bit for bit.
TEST_F(MeshLoaderTest, FarFromTheOriginKeepsDoublesNearItRoundsToFloat32) {
  const auto grid = [](double x0, double y0, double z) {
    std::string obj;
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) {
        char line[96];
        std::snprintf(line, sizeof line, "v %.3f %.3f %.3f\n", x0 + 0.3 * i, y0 + 0.3 * j, z);
        obj += line;
      }
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) {
        const int a = 1 + j * 3 + i;
        obj += "f " + std::to_string(a) + " " + std::to_string(a + 1) + " " + std::to_string(a + 4) + "\n";
        obj += "f " + std::to_string(a) + " " + std::to_string(a + 4) + " " + std::to_string(a + 3) + "\n";
      }
    return obj;
  };
  const LoadedSurface far = load_surface(write("utm.obj", grid(500000.0, 5400000.0, 120.1)));
  ASSERT_EQ(far.mesh.vertex_count(), 9);
  EXPECT_TRUE(far.warnings.empty()) << far.warnings.front();
  EXPECT_EQ(far.mesh.positions[4], glm::dvec3(500000.3, 5400000.3, 120.1));
  EXPECT_NEAR(surface_area(far.mesh), 0.36, 1e-9);
  const LoadedSurface near = load_surface(write("near.obj", grid(0.1, 0, 0.1)));
  EXPECT_EQ(near.mesh.positions[0], glm::dvec3(double(0.1f), 0, double(0.1f)));
}

std::uint64_t directed(int a, int b) { return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b); }

// The invariants SurfaceMesh promises: valid indices, consistent orientation (each directed edge
// at most once), and a boundary loop that walks every boundary edge along its direction.
void expect_valid_surface(const SurfaceMesh& mesh) {
  std::set<std::uint64_t> sides;
  for (const glm::ivec3& t : mesh.triangles)
    for (int c = 0; c < 3; ++c) {
      const int a = t[c], b = t[(c + 1) % 3];
      ASSERT_GE(a, 0);
      ASSERT_LT(a, mesh.vertex_count());
      EXPECT_TRUE(sides.insert(directed(a, b)).second) << "directed edge " << a << "->" << b << " used twice";
    }
  int boundary_edges = 0;
  for (std::uint64_t side : sides)
    if (!sides.count(directed(int(side & 0xffffffffu), int(side >> 32)))) ++boundary_edges;
  std::set<int> on_loops;
  for (const std::vector<int>& loop : mesh.boundary_loops)
    for (size_t i = 0; i < loop.size(); ++i) {
      EXPECT_TRUE(on_loops.insert(loop[i]).second) << "vertex " << loop[i] << " is on the loops twice";
      const int a = loop[i], b = loop[(i + 1) % loop.size()];
      EXPECT_TRUE(sides.count(directed(a, b))) << "loop step " << a << "->" << b << " is not a face side";
      EXPECT_FALSE(sides.count(directed(b, a))) << "loop step " << a << "->" << b << " is not a boundary edge";
    }
  EXPECT_EQ(int(on_loops.size()), boundary_edges) << "the loops hold every boundary edge";
  std::vector<char> used(mesh.positions.size(), 0);
  for (const glm::ivec3& t : mesh.triangles) used[t.x] = used[t.y] = used[t.z] = 1;
  for (size_t v = 0; v < used.size(); ++v) EXPECT_TRUE(used[v]) << "vertex " << v << " is unreferenced";
}

// An OBJ of an nx x ny grid of unit quads in the z = 0 plane, as quads or split into triangles.
std::string grid_obj(int nx, int ny, bool quads) {
  std::ostringstream out;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) out << "v " << i << ' ' << j << " 0\n";
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int a = j * (nx + 1) + i + 1, b = a + 1, c = a + nx + 1, d = c + 1;
      if (quads) out << "f " << a << ' ' << b << ' ' << d << ' ' << c << '\n';
      else out << "f " << a << ' ' << b << ' ' << d << "\nf " << a << ' ' << d << ' ' << c << '\n';
    }
  return out.str();
}

// Real scans (assets/scanned), loaded once for the suite.
fs::path scanned(const std::string& name) { return fs::path(PAVER_SOURCE_DIR) / "assets/scanned" / name; }

const LoadedSurface& real_mesh(const std::string& name) {
  static std::map<std::string, LoadedSurface> cache;
  auto found = cache.find(name);
  if (found == cache.end()) found = cache.emplace(name, load_surface(scanned(name))).first;
  return found->second;
}

// ---------------------------------------------------------------------------------------------
// Real meshes

TEST(MeshLoaderRealMeshes, BunnyheadCountsAndBoundary) {
  const LoadedSurface& loaded = real_mesh("bunnyhead.obj");
  EXPECT_EQ(loaded.mesh.face_count(), 3000);
  EXPECT_EQ(loaded.mesh.vertex_count(), 1550);
  EXPECT_EQ(loaded.mesh.outer_loop().size(), 98u);
  EXPECT_TRUE(loaded.warnings.empty()) << loaded.warnings.front();
  expect_valid_surface(loaded.mesh);
}

// A scanned band and a scan with two holes load with every loop, the longest (in 3D) first.
TEST(MeshLoaderRealMeshes, BandAndHolesLoadWithEveryLoopTheLongestFirst) {
  const std::pair<const char*, std::vector<size_t>> cases[] = {{"bunnyhead_band.obj", {125, 33}},
                                                               {"bunnyhead_three_loops.obj", {59, 33, 32}}};
  for (const auto& [name, expected_sizes] : cases) {
    const SurfaceMesh& mesh = real_mesh(name).mesh;
    std::vector<size_t> sizes;
    for (const auto& loop : mesh.boundary_loops) sizes.push_back(loop.size());
    std::vector<size_t> sorted = sizes;
    std::sort(sorted.rbegin(), sorted.rend());
    EXPECT_EQ(sorted, expected_sizes) << name;
    ASSERT_FALSE(mesh.boundary_loops.empty());
    const auto loop_length = [&](const std::vector<int>& loop) {
      double length = 0;
      for (size_t k = 0; k < loop.size(); ++k)
        length += glm::length(mesh.positions[loop[(k + 1) % loop.size()]] - mesh.positions[loop[k]]);
      return length;
    };
    for (const auto& loop : mesh.boundary_loops)
      EXPECT_LE(loop_length(loop), loop_length(mesh.outer_loop())) << name << ": the outer loop is the longest";
    expect_valid_surface(mesh);
  }
}

TEST(MeshLoaderRealMeshes, MazeCountsAndBoundary) {
  const LoadedSurface& loaded = real_mesh("maze.obj");
  EXPECT_EQ(loaded.mesh.face_count(), 9174);
  EXPECT_EQ(loaded.mesh.vertex_count(), 6120);
  EXPECT_EQ(loaded.mesh.outer_loop().size(), 3064u);
  expect_valid_surface(loaded.mesh);
}

TEST(MeshLoaderRealMeshes, AreaAndDiagonalArePositive) {
  const SurfaceMesh& mesh = real_mesh("bunnyhead.obj").mesh;
  EXPECT_GT(surface_area(mesh), 0.0);
  EXPECT_GT(bounding_box_diagonal(mesh), 0.0);
}

// ---------------------------------------------------------------------------------------------
// Positive cases per format

TEST_F(MeshLoaderTest, QuadGridIsTriangulated) {
  const LoadedSurface loaded = load_surface(write("grid.obj", grid_obj(4, 3, true)));
  EXPECT_EQ(loaded.mesh.face_count(), 2 * 12);
  EXPECT_EQ(loaded.mesh.vertex_count(), 20);
  EXPECT_EQ(loaded.mesh.outer_loop().size(), 14u);
  EXPECT_TRUE(loaded.warnings.empty());
  EXPECT_NEAR(surface_area(loaded.mesh), 12.0, 1e-12);
  EXPECT_NEAR(bounding_box_diagonal(loaded.mesh), 5.0, 1e-12);
  expect_valid_surface(loaded.mesh);
}

TEST_F(MeshLoaderTest, NonConvexPolygonIsEarClipped) {
  // A U shape: a fan from its first vertex would fold over the notch.
  const LoadedSurface loaded = load_surface(write("u.obj",
                                                  "v 0 0 0\nv 3 0 0\nv 3 3 0\nv 2 3 0\nv 2 1 0\nv 1 1 0\nv 1 3 0\n"
                                                  "v 0 3 0\nf 1 2 3 4 5 6 7 8\n"));
  ASSERT_EQ(loaded.mesh.face_count(), 6);
  EXPECT_NEAR(surface_area(loaded.mesh), 7.0, 1e-12);
  for (const glm::ivec3& t : loaded.mesh.triangles) {
    const glm::dvec3& a = loaded.mesh.positions[t.x];
    const double z = glm::cross(loaded.mesh.positions[t.y] - a, loaded.mesh.positions[t.z] - a).z;
    EXPECT_GT(z, 0.0) << "a triangle is folded over";
  }
  expect_valid_surface(loaded.mesh);
}

TEST_F(MeshLoaderTest, CollinearPolygonVerticesAreKept) {
  // A square with a vertex in the middle of each side, as one octagon.
  const LoadedSurface loaded = make_surface(
      {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {2, 2, 0}, {1, 2, 0}, {0, 2, 0}, {0, 1, 0}},
      {{0, 1, 2, 3, 4, 5, 6, 7}}, "octagon");
  EXPECT_EQ(loaded.mesh.face_count(), 6);
  EXPECT_EQ(loaded.dropped_degenerate_faces, 0);
  EXPECT_NEAR(surface_area(loaded.mesh), 4.0, 1e-12);
  EXPECT_EQ(loaded.mesh.outer_loop().size(), 8u);
  expect_valid_surface(loaded.mesh);
}

TEST_F(MeshLoaderTest, SelfIntersectingPolygonFallsBackToFan) {
  // A pentagram: no ear exists, so the polygon becomes a fan; its topology is still a disk.
  std::vector<glm::dvec3> positions;
  for (int i = 0; i < 5; ++i) {
    const double angle = 2 * std::numbers::pi * i / 5;
    positions.emplace_back(std::cos(angle), std::sin(angle), 0);
  }
  const LoadedSurface loaded = make_surface(positions, {{0, 2, 4, 1, 3}}, "pentagram");
  EXPECT_EQ(loaded.mesh.face_count(), 3);
  EXPECT_EQ(loaded.mesh.outer_loop().size(), 5u);
  expect_valid_surface(loaded.mesh);
}

// --region: a solid ring's outer face alone is a band, its borders rims; the whole ring is closed.
TEST_F(MeshLoaderTest, ARegionKeepsTheNamedPartsOnly) {
  const fs::path ring = write("solid_ring.obj", test::solid_ring_obj(60, 4));
  const LoadedSurface whole = load_surface(ring);
  EXPECT_TRUE(whole.mesh.boundary_loops.empty());
  EXPECT_EQ(whole.mesh.face_count(), 2 * (60 * 4 * 2 + 60 * 2));
  const LoadedSurface outer = load_surface(ring, {"outer"});
  EXPECT_TRUE(outer.warnings.empty()) << outer.warnings.at(0);
  EXPECT_EQ(outer.mesh.face_count(), 2 * 60 * 4) << "every face of the group, the first too";
  EXPECT_EQ(outer.mesh.vertex_count(), 60 * 5);
  EXPECT_EQ(outer.mesh.boundary_loops.size(), 2u) << "a band";
  for (const glm::dvec3& p : outer.mesh.positions) EXPECT_NEAR(std::hypot(p.x, p.y), 10.0, 1e-4);
  const LoadedSurface outer_and_top = load_surface(ring, {"outer", "top"});
  EXPECT_EQ(outer_and_top.mesh.face_count(), 2 * 60 * 5);
  EXPECT_EQ(outer_and_top.mesh.boundary_loops.size(), 2u);
  // The object's name (`o ring`) names every face.
  EXPECT_EQ(load_surface(ring, {"ring"}).mesh.face_count(), whole.mesh.face_count());
  expect_valid_surface(outer.mesh);
}

TEST_F(MeshLoaderTest, ARegionTheFileDoesNotNameIsRefusedListingItsParts) {
  const fs::path ring = write("solid_ring.obj", test::solid_ring_obj(12, 2));
  std::string message = error_of([&] { load_surface(ring, {"outr"}); });
  EXPECT_TRUE(Contains(message, "--region outr: the file has no part of that name; it has ring, outer, inner, top, bottom"))
      << message;
  const fs::path plain = write("plain.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  message = error_of([&] { load_surface(plain, {"outer"}); });
  EXPECT_TRUE(Contains(message, "the file names no parts")) << message;
}

TEST_F(MeshLoaderTest, ReadsOff) {
  const LoadedSurface loaded =
      load_surface(write("square.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n"));
  EXPECT_EQ(loaded.mesh.face_count(), 2);
  EXPECT_EQ(loaded.mesh.outer_loop().size(), 4u);
  expect_valid_surface(loaded.mesh);
}

TEST_F(MeshLoaderTest, ReadsAsciiPly) {
  const LoadedSurface loaded = load_surface(write("square.ply",
                                                  "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\n"
                                                  "property float y\nproperty float z\nelement face 2\n"
                                                  "property list uchar int vertex_indices\nend_header\n"
                                                  "0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n"));
  EXPECT_EQ(loaded.mesh.face_count(), 2);
  EXPECT_EQ(loaded.mesh.vertex_count(), 4);
  expect_valid_surface(loaded.mesh);
}

std::string stl_facet(const char* a, const char* b, const char* c) {
  return std::string("facet normal 0 0 1\nouter loop\nvertex ") + a + "\nvertex " + b + "\nvertex " + c +
         "\nendloop\nendfacet\n";
}

TEST_F(MeshLoaderTest, ObjAndPlyFacesExportedApartAreJoinedLikeStls) {
  // Every face with corners of its own: it paved one triangle of the grid, the "largest component".
  std::string obj, ply_vertices, ply_faces;
  int faces = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (const auto& t : {std::array<std::array<int, 2>, 3>{{{i, j}, {i + 1, j}, {i + 1, j + 1}}},
                            std::array<std::array<int, 2>, 3>{{{i, j}, {i + 1, j + 1}, {i, j + 1}}}}) {
        for (const auto& [x, y] : t) {
          obj += "v " + std::to_string(x) + " " + std::to_string(y) + " 0\n";
          ply_vertices += std::to_string(x) + " " + std::to_string(y) + " 0\n";
        }
        const int k = 3 * faces++;
        obj += "f " + std::to_string(k + 1) + " " + std::to_string(k + 2) + " " + std::to_string(k + 3) + "\n";
        ply_faces += "3 " + std::to_string(k) + " " + std::to_string(k + 1) + " " + std::to_string(k + 2) + "\n";
      }
  const std::string ply = "ply\nformat ascii 1.0\nelement vertex " + std::to_string(3 * faces) +
                          "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
                          std::to_string(faces) + "\nproperty list uchar int vertex_indices\nend_header\n" +
                          ply_vertices + ply_faces;
  for (const LoadedSurface& loaded : {load_surface(write("soup.obj", obj)), load_surface(write("soup.ply", ply))}) {
    EXPECT_EQ(loaded.mesh.face_count(), 32);
    EXPECT_EQ(loaded.mesh.vertex_count(), 25);
    EXPECT_EQ(loaded.dropped_components, 0);
    ASSERT_FALSE(loaded.warnings.empty());
    EXPECT_NE(loaded.warnings[0].find("joined 71 vertices at exactly the position of another"), std::string::npos)
        << loaded.warnings[0];
    EXPECT_EQ(loaded.warnings.size(), 1u) << "no second warning for the vertices the join left unused";
    expect_valid_surface(loaded.mesh);
  }
}

TEST_F(MeshLoaderTest, ReadsAsciiStlAndMergesCorners) {
  const LoadedSurface loaded = load_surface(write(
      "square.STL", "solid square\n" + stl_facet("0 0 0", "1 0 0", "1 1 0") + stl_facet("0 0 0", "1 1 0", "0 1 0") +
                        "endsolid square\n"));
  EXPECT_EQ(loaded.mesh.face_count(), 2);
  EXPECT_EQ(loaded.mesh.vertex_count(), 4);
  expect_valid_surface(loaded.mesh);
}

TEST_F(MeshLoaderTest, StlDegenerateFacetIsCounted) {
  // Welding merges the repeated corner and the reader leaves the facet out; it must still be reported.
  const LoadedSurface loaded = load_surface(write(
      "square.stl", "solid square\n" + stl_facet("0 0 0", "1 0 0", "1 1 0") + stl_facet("0 0 0", "1 1 0", "0 1 0") +
                        stl_facet("0 0 0", "0 0 0", "0 1 0") + "endsolid square\n"));
  EXPECT_EQ(loaded.mesh.face_count(), 2);
  EXPECT_EQ(loaded.dropped_degenerate_faces, 1);
  EXPECT_TRUE(any_warning_contains(loaded, "dropped 1 degenerate face"));
}

TEST_F(MeshLoaderTest, ReadsBinaryStl) {
  std::string bytes(80, ' ');
  auto put_u32 = [&](std::uint32_t v) {
    for (int i = 0; i < 4; ++i) bytes.push_back(char((v >> (8 * i)) & 0xff));
  };
  auto put_float = [&](float f) {
    std::uint32_t v;
    std::memcpy(&v, &f, 4);
    put_u32(v);
  };
  put_u32(2);
  const float corners[2][3][3] = {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, {{0, 0, 0}, {1, 1, 0}, {0, 1, 0}}};
  for (const auto& triangle : corners) {
    for (float n : {0.f, 0.f, 1.f}) put_float(n);
    for (const auto& corner : triangle)
      for (float x : corner) put_float(x);
    bytes += std::string(2, '\0');
  }
  const LoadedSurface loaded = load_surface(write("square.stl", bytes));
  EXPECT_EQ(loaded.mesh.face_count(), 2);
  expect_valid_surface(loaded.mesh);
}

TEST_F(MeshLoaderTest, MakeSurfaceBuildsFromMemory) {
  const LoadedSurface loaded =
      make_surface({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2, 3}}, "in-memory square");
  EXPECT_EQ(loaded.mesh.face_count(), 2);
  EXPECT_NEAR(surface_area(loaded.mesh), 1.0, 1e-15);
  expect_valid_surface(loaded.mesh);
}

TEST_F(MeshLoaderTest, LargeGridIsHandled) {
  const int n = 200;  // 79,202 triangles
  std::vector<glm::dvec3> positions;
  std::vector<std::vector<int>> faces;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) positions.emplace_back(i, j, 0.1 * std::sin(0.3 * i) * std::cos(0.2 * j));
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const int a = j * n + i;
      faces.push_back({a, a + 1, a + n + 1});
      faces.push_back({a, a + n + 1, a + n});
    }
  const LoadedSurface loaded = make_surface(std::move(positions), faces, "grid");
  EXPECT_EQ(loaded.mesh.face_count(), 2 * (n - 1) * (n - 1));
  EXPECT_EQ(loaded.mesh.outer_loop().size(), size_t(4 * (n - 1)));
}

// ---------------------------------------------------------------------------------------------
// Files that cannot be read

TEST_F(MeshLoaderTest, MissingFileIsReported) {
  const std::string message = load_error(dir_ / "nowhere.obj");
  EXPECT_TRUE(Contains(message, "nowhere.obj"));
  EXPECT_TRUE(Contains(message, "not found"));
}

TEST_F(MeshLoaderTest, UnsupportedExtensionListsFormats) {
  const std::string message = load_error(write("mesh.3ds", "whatever"));
  EXPECT_TRUE(Contains(message, ".3ds"));
  EXPECT_TRUE(Contains(message, "OBJ, OFF, PLY"));
  EXPECT_TRUE(Contains(message, "STL"));
}

TEST_F(MeshLoaderTest, EmptyFileContainsNoFaces) {
  const std::string message = load_error(write("empty.obj", ""));
  EXPECT_TRUE(Contains(message, "empty.obj: "));
  EXPECT_TRUE(Contains(message, "contains no faces"));
}

TEST_F(MeshLoaderTest, PointCloudContainsNoFaces) {
  EXPECT_TRUE(Contains(load_error(write("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n")), "contains no faces"));
}

// ---------------------------------------------------------------------------------------------
// Malformed text: the line is named

TEST_F(MeshLoaderTest, ObjVertexWithTwoCoordinates) {
  const std::string message = load_error(write("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1\nf 1 2 3\n"));
  EXPECT_TRUE(Contains(message, "bad.obj: line 3"));
  EXPECT_TRUE(Contains(message, "3 coordinates"));
}

TEST_F(MeshLoaderTest, ObjVertexWithNonNumber) {
  const std::string message = load_error(write("bad.obj", "# a comment\nv 0 0 0\nv 1 x 0\nv 0 1 0\nf 1 2 3\n"));
  EXPECT_TRUE(Contains(message, "line 3"));
  EXPECT_TRUE(Contains(message, "'x' is not a number"));
}

TEST_F(MeshLoaderTest, ObjFaceWithTwoVertices) {
  const std::string message = load_error(write("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2\n"));
  EXPECT_TRUE(Contains(message, "line 5"));
  EXPECT_TRUE(Contains(message, "at least 3 vertices"));
}

TEST_F(MeshLoaderTest, ObjFaceIndexOutOfRange) {
  const std::string message = load_error(write("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 3 7\n"));
  EXPECT_TRUE(Contains(message, "line 5"));
  EXPECT_TRUE(Contains(message, "vertex 7"));
  EXPECT_TRUE(Contains(message, "only 3 vertices"));
}

TEST_F(MeshLoaderTest, ObjFaceIndexZero) {
  const std::string message = load_error(write("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"));
  EXPECT_TRUE(Contains(message, "line 4"));
  EXPECT_TRUE(Contains(message, "start at 1"));
}

TEST_F(MeshLoaderTest, ObjRelativeIndices) {
  const LoadedSurface loaded = load_surface(write("relative.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n"));
  EXPECT_EQ(loaded.mesh.face_count(), 1);
  const std::string message = load_error(write("bad.obj", "v 0 0 0\nv 1 0 0\nf -3 -2 -1\nv 0 1 0\n"));
  EXPECT_TRUE(Contains(message, "line 3"));
  EXPECT_TRUE(Contains(message, "relative index -3"));
}

TEST_F(MeshLoaderTest, ObjTrailingCommentsAreIgnored) {
  const LoadedSurface loaded =
      load_surface(write("comments.obj", "v 0 0 0 # origin\nv 1 0 0\nv 0 1 0\nf 1 2 3 # the only face\n"));
  EXPECT_EQ(loaded.mesh.face_count(), 1);
}

TEST_F(MeshLoaderTest, ObjFaceCornerWithTextureAndNormal) {
  const LoadedSurface loaded =
      load_surface(write("uv.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\nf 1/1/1 2/1/1 3//1\n"));
  EXPECT_EQ(loaded.mesh.face_count(), 1);
  EXPECT_TRUE(Contains(load_error(write("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/a 2 3\n")), "line 4"));
}

TEST_F(MeshLoaderTest, OffHeaderMustBeOff) {
  const std::string message = load_error(write("bad.off", "OFX\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"));
  EXPECT_TRUE(Contains(message, "bad.off: line 1"));
  EXPECT_TRUE(Contains(message, "'OFF'"));
}

TEST_F(MeshLoaderTest, OffCountsOnTheHeaderLineAreNamed) {
  // The counts belong on a line of their own.
  const std::string message = load_error(write("bad.off", "OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"));
  EXPECT_TRUE(Contains(message, "line 1"));
  EXPECT_TRUE(Contains(message, "'3 1 0'"));
}

TEST_F(MeshLoaderTest, OffCountsMustFollowHeader) {
  const std::string message = load_error(write("bad.off", "OFF\nthree 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"));
  EXPECT_TRUE(Contains(message, "line 2"));
  EXPECT_TRUE(Contains(message, "counts"));
}

TEST_F(MeshLoaderTest, OffCountsMustMatchLines) {
  const std::string missing = load_error(write("short.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"));
  EXPECT_TRUE(Contains(missing, "declare 4 vertices and 1 face"));
  const std::string extra = load_error(write("long.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 1\n"));
  EXPECT_TRUE(Contains(extra, "declare 3 vertices and 1 face"));
  EXPECT_TRUE(Contains(extra, "5 non-empty lines"));
}

TEST_F(MeshLoaderTest, OffFaceIndexOutOfRange) {
  const std::string message = load_error(write("bad.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"));
  EXPECT_TRUE(Contains(message, "line 6"));
  EXPECT_TRUE(Contains(message, "out of range"));
}

TEST_F(MeshLoaderTest, OffCommentIsNamed) {
  const std::string message =
      load_error(write("bad.off", "OFF\n3 1 0\n# made by hand\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"));
  EXPECT_TRUE(Contains(message, "line 3"));
  EXPECT_TRUE(Contains(message, "comment"));
}

TEST_F(MeshLoaderTest, PlyThatCannotBeParsed) {
  const std::string message = load_error(write("bad.ply", "this is not a ply file\n"));
  EXPECT_TRUE(Contains(message, "could not parse it as PLY"));
  EXPECT_TRUE(Contains(message, "'ply'"));
}

const char* const kPlyHeader =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n";  // data starts on line 10

TEST_F(MeshLoaderTest, PlyAsciiValueNamesLine) {
  const std::string message =
      load_error(write("bad.ply", std::string(kPlyHeader) + "0 0 0\n1 0 0\n0 one 0\n3 0 1 2\n"));
  EXPECT_TRUE(Contains(message, "line 12"));
  EXPECT_TRUE(Contains(message, "'one' is not a number"));
}

TEST_F(MeshLoaderTest, PlyAsciiFaceIndexOutOfRange) {
  const std::string message = load_error(write("bad.ply", std::string(kPlyHeader) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"));
  EXPECT_TRUE(Contains(message, "line 13"));
  EXPECT_TRUE(Contains(message, "refers to vertex 3"));
}

TEST_F(MeshLoaderTest, PlyAsciiNanNamesLine) {
  const std::string message =
      load_error(write("nan.ply", std::string(kPlyHeader) + "0 0 0\n1 0 0\n0 nan 0\n3 0 1 2\n"));
  EXPECT_TRUE(Contains(message, "line 12"));
  EXPECT_TRUE(Contains(message, "1 vertex has NaN or infinite"));
}

TEST_F(MeshLoaderTest, PlyHeaderIsCheckedStrictly) {
  // A property before any element.
  const std::string message = load_error(write("bad.ply", "ply\nformat ascii 1.0\nproperty float x\nend_header\n"));
  EXPECT_TRUE(Contains(message, "could not parse it as PLY"));
  EXPECT_TRUE(Contains(message, "line 3"));
}

TEST_F(MeshLoaderTest, PlyPointCloudContainsNoFaces) {
  const std::string message = load_error(write("points.ply",
                                               "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                                               "property float y\nproperty float z\nend_header\n0 0 0\n"));
  EXPECT_TRUE(Contains(message, "contains no faces"));
}

TEST_F(MeshLoaderTest, ReadsBinaryPly) {
  std::string bytes =
      "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const float corners[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  for (float x : corners) {
    std::uint32_t v;
    std::memcpy(&v, &x, 4);
    for (int i = 0; i < 4; ++i) bytes.push_back(char((v >> (8 * i)) & 0xff));
  }
  bytes.push_back(4);
  for (int index : {0, 1, 2, 3})
    for (int i = 0; i < 4; ++i) bytes.push_back(char((std::uint32_t(index) >> (8 * i)) & 0xff));
  const LoadedSurface loaded = load_surface(write("square.ply", bytes));
  EXPECT_EQ(loaded.mesh.face_count(), 2);
  EXPECT_NEAR(surface_area(loaded.mesh), 1.0, 1e-12);
  expect_valid_surface(loaded.mesh);
}

TEST_F(MeshLoaderTest, TruncatedBinaryPlyIsMeasured) {
  const std::string header =
      "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
      "property float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n";
  const std::string message = load_error(write("cut.ply", header + std::string(20, '\0')));
  EXPECT_TRUE(Contains(message, "could not parse it as PLY"));
  EXPECT_TRUE(Contains(message, "size mismatch"));
}

TEST_F(MeshLoaderTest, TruncatedBinaryStlIsMeasured) {
  std::string bytes(80, 'x');
  bytes += std::string("\x03\0\0\0", 4);  // 3 triangles declared...
  bytes += std::string(100, '\0');         // ...but 2 present
  const std::string message = load_error(write("cut.stl", bytes));
  EXPECT_TRUE(Contains(message, "could not parse it as STL"));
  EXPECT_TRUE(Contains(message, "size mismatch"));
  EXPECT_TRUE(Contains(message, "3 triangles"));
}

// ---------------------------------------------------------------------------------------------
// Non-finite coordinates

TEST_F(MeshLoaderTest, NanCoordinateNamesLineAndCount) {
  const std::string message =
      load_error(write("nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nv 0 inf 1\nf 1 2 3\nf 1 3 4\n"));
  EXPECT_TRUE(Contains(message, "line 2"));
  EXPECT_TRUE(Contains(message, "vertex 2"));
  EXPECT_TRUE(Contains(message, "2 vertices have NaN or infinite"));
}

TEST_F(MeshLoaderTest, NanCoordinateInOff) {
  const std::string message = load_error(write("nan.off", "OFF\n3 1 0\n0 0 0\n1 -inf 0\n0 1 0\n3 0 1 2\n"));
  EXPECT_TRUE(Contains(message, "line 4"));
  EXPECT_TRUE(Contains(message, "non-finite"));
}

TEST_F(MeshLoaderTest, NanCoordinateInMemoryNamesVertex) {
  const std::string message = error_of([] {
    make_surface({{0, 0, 0}, {1, 0, 0}, {0, std::nan(""), 0}}, {{0, 1, 2}}, "memory");
  });
  EXPECT_TRUE(Contains(message, "memory: vertex 2"));
  EXPECT_TRUE(Contains(message, "1 vertex has NaN or infinite"));
}

TEST_F(MeshLoaderTest, MakeSurfaceRejectsBadIndex) {
  const std::string message =
      error_of([] { make_surface({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 5}}, "memory"); });
  EXPECT_TRUE(Contains(message, "refers to vertex 5"));
}

// ---------------------------------------------------------------------------------------------
// Repairs

TEST_F(MeshLoaderTest, DegenerateFacesAreDroppedAndCounted) {
  // A unit square in two triangles, plus a zero-area sliver on its edge and a face with a repeated
  // vertex (the reader drops the latter itself; it must still be counted).
  const LoadedSurface loaded = load_surface(
      write("degenerate.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 0 0\nf 1 2 3\nf 1 3 4\nf 1 5 2\nf 1 2 2\n"));
  EXPECT_EQ(loaded.dropped_degenerate_faces, 2);
  EXPECT_TRUE(any_warning_contains(loaded, "dropped 2 degenerate faces"));
  EXPECT_EQ(loaded.mesh.face_count(), 2);
  EXPECT_EQ(loaded.mesh.vertex_count(), 4);
  expect_valid_surface(loaded.mesh);
}

TEST_F(MeshLoaderTest, RepeatedVertexTriangleInMemoryIsDegenerate) {
  const LoadedSurface loaded =
      make_surface({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 2}}, "memory");
  EXPECT_EQ(loaded.dropped_degenerate_faces, 1);
  EXPECT_EQ(loaded.mesh.face_count(), 1);
}

TEST_F(MeshLoaderTest, OnlyDegenerateFacesLeaveNothing) {
  const std::string message = load_error(write("flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n"));
  EXPECT_TRUE(Contains(message, "contains no faces after dropping 1 degenerate face"));
}

TEST_F(MeshLoaderTest, UnreferencedVerticesAreDropped) {
  const LoadedSurface loaded =
      load_surface(write("extra.obj", "v 5 5 5\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 9 9 9\nf 2 3 4\n"));
  EXPECT_EQ(loaded.mesh.vertex_count(), 3);
  EXPECT_TRUE(any_warning_contains(loaded, "dropped 2 unreferenced vertices"));
  EXPECT_EQ(loaded.mesh.positions[0], glm::dvec3(0, 0, 0));
  expect_valid_surface(loaded.mesh);
}

TEST_F(MeshLoaderTest, InconsistentOrientationIsRepaired) {
  // Three triangles of a strip; the middle one is wound the other way.
  const LoadedSurface loaded = load_surface(
      write("flipped.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 2 1 0\nf 1 2 3\nf 2 3 4\nf 2 5 4\n"));
  EXPECT_EQ(loaded.mesh.face_count(), 3);
  EXPECT_TRUE(any_warning_contains(loaded, "reoriented 1 face"));
  expect_valid_surface(loaded.mesh);
}

TEST_F(MeshLoaderTest, LargestComponentIsKept) {
  std::string obj = grid_obj(2, 2, false);  // 8 triangles, vertices 1..9
  obj += "v 10 10 0\nv 11 10 0\nv 10 11 0\nf 10 11 12\n";
  const LoadedSurface loaded = load_surface(write("two.obj", obj));
  EXPECT_EQ(loaded.mesh.face_count(), 8);
  EXPECT_EQ(loaded.mesh.vertex_count(), 9);
  EXPECT_EQ(loaded.dropped_components, 1);
  EXPECT_TRUE(any_warning_contains(loaded, "2 connected components"));
  EXPECT_TRUE(any_warning_contains(loaded, "(1 face)"));
  expect_valid_surface(loaded.mesh);
}

// ---------------------------------------------------------------------------------------------
// Topology Paver cannot pave

TEST_F(MeshLoaderTest, NonManifoldEdgeIsRefused) {
  // Three triangles on the edge 1-2 (a fin).
  const std::string message = load_error(
      write("fin.obj", "v 0 0 0\nv 1 0 0\nv 0.5 1 0\nv 0.5 -1 0\nv 0.5 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n"));
  EXPECT_TRUE(Contains(message, "fin.obj: "));
  EXPECT_TRUE(Contains(message, "1 non-manifold edge"));
  EXPECT_TRUE(Contains(message, "vertices 0 and 1"));
}

// Two triangles touching at a vertex: split there, they are two pieces, and the larger is kept.
TEST_F(MeshLoaderTest, ABowtieVertexIsSplitWithAWarning) {
  const LoadedSurface loaded =
      load_surface(write("bowtie.obj", "v 0 0 0\nv 1 1 0\nv 1 -1 0\nv -2 2 0\nv -2 -2 0\nf 1 2 3\nf 1 4 5\n"));
  EXPECT_EQ(loaded.mesh.face_count(), 1);
  EXPECT_EQ(loaded.dropped_components, 1);
  ASSERT_GE(loaded.warnings.size(), 2u);
  EXPECT_TRUE(Contains(loaded.warnings[0], "split 1 vertex where separate fans of faces met at one point"))
      << loaded.warnings[0];
  EXPECT_TRUE(Contains(loaded.warnings[1], "kept the largest")) << loaded.warnings[1];
  expect_valid_surface(loaded.mesh);
}

// A vertex no face uses, at the bowtie's position and numbered before it, is not taken as the
// second fan's vertex: the split is a copy, said as one, and the unused vertex is dropped and said.
TEST_F(MeshLoaderTest, AnUnusedVertexAtABowtieIsNotTakenForAFan) {
  const LoadedSurface loaded = load_surface(
      write("bowtie_unused.obj", "v 0 0 0\nv 0 0 0\nv 1 1 0\nv 1 -1 0\nv -2 2 0\nv -2 -2 0\nf 2 3 4\nf 2 5 6\n"));
  std::string said;
  for (const std::string& w : loaded.warnings) said += w + "\n";
  EXPECT_TRUE(Contains(said, "split 1 vertex")) << said;
  EXPECT_TRUE(Contains(said, "dropped 1 unreferenced vertex")) << said;
  EXPECT_FALSE(Contains(said, "joined")) << said;
  EXPECT_EQ(loaded.mesh.face_count(), 1);
  expect_valid_surface(loaded.mesh);
}

TEST_F(MeshLoaderTest, ConesTouchingAtTheTipAreSplitThere) {
  std::vector<glm::dvec3> positions = {{0, 0, 0}};
  std::vector<std::vector<int>> faces;
  const int n = 6;
  for (int cone = 0; cone < 2; ++cone) {
    const int first = int(positions.size());
    const double z = cone == 0 ? 1.0 : -1.0;
    for (int i = 0; i < n; ++i) {
      const double angle = 2 * std::numbers::pi * i / n;
      positions.emplace_back(std::cos(angle), std::sin(angle), z);
    }
    for (int i = 0; i < n; ++i) faces.push_back({0, first + i, first + (i + 1) % n});
  }
  const LoadedSurface loaded = make_surface(positions, faces, "cones");
  EXPECT_EQ(loaded.mesh.face_count(), n) << "one cone, a disk, is kept";
  EXPECT_EQ(loaded.mesh.boundary_loops.size(), 1u);
  EXPECT_TRUE(Contains(loaded.warnings.at(0), "cones: split 1 vertex")) << loaded.warnings[0];
  expect_valid_surface(loaded.mesh);
}

// A strip bent round until its outer corners meet at one point, the inner ones apart: a disk whose
// rim touches itself. `shared_corner`: the file uses one vertex there (a bowtie of its own) rather
// than two at one position (what scanners and CAD exports write).
std::pair<std::vector<glm::dvec3>, std::vector<std::vector<int>>> strip_touching_itself(bool shared_corner) {
  const int n = 8;
  std::vector<glm::dvec3> positions;
  std::vector<std::vector<int>> faces;
  for (int i = 0; i <= n; ++i) {
    const double outer = 2 * std::numbers::pi * i / n, inner = outer * (n - 0.5) / n;
    positions.emplace_back(2 * std::cos(outer), 2 * std::sin(outer), 0);  // 2i
    positions.emplace_back(std::cos(inner), std::sin(inner), 0);          // 2i + 1
  }
  positions[2 * n] = positions[0];  // exactly, not through the cosine's rounding
  for (int i = 0; i < n; ++i) {
    const int next_outer = shared_corner && i + 1 == n ? 0 : 2 * (i + 1);
    faces.push_back({2 * i, next_outer, 2 * (i + 1) + 1, 2 * i + 1});
  }
  return {positions, faces};
}

TEST_F(MeshLoaderTest, TwoVerticesAtOnePointAreNotJoinedIntoABowtie) {
  auto [positions, faces] = strip_touching_itself(false);
  const LoadedSurface loaded = make_surface(positions, faces, "strip");
  EXPECT_TRUE(loaded.warnings.empty()) << "a good surface needs no repair: " << loaded.warnings.at(0);
  EXPECT_EQ(loaded.mesh.vertex_count(), int(positions.size()));
  EXPECT_EQ(loaded.mesh.face_count(), 16);
  EXPECT_EQ(loaded.mesh.boundary_loops.size(), 1u) << "a disk, its rim touching itself";
  expect_valid_surface(loaded.mesh);
}

TEST_F(MeshLoaderTest, AFilesOwnBowtieVertexIsSplitIntoADisk) {
  auto [positions, faces] = strip_touching_itself(true);
  const LoadedSurface loaded = make_surface(positions, faces, "strip");
  ASSERT_EQ(loaded.warnings.size(), 2u);  // the split, and the unused vertex at the corner
  EXPECT_TRUE(Contains(loaded.warnings[0], "strip: split 1 vertex")) << loaded.warnings[0];
  EXPECT_EQ(loaded.dropped_components, 0);
  EXPECT_EQ(loaded.mesh.face_count(), 16);
  EXPECT_EQ(loaded.mesh.vertex_count(), int(positions.size()));
  EXPECT_EQ(loaded.mesh.boundary_loops.size(), 1u);
  expect_valid_surface(loaded.mesh);
}

// Three squares exported apart along one line: joining them would put three faces on an edge, so
// they stay apart (three pieces; the largest kept) rather than being refused as a fin.
TEST_F(MeshLoaderTest, JoiningThatWouldMakeAFinIsUndone) {
  std::vector<glm::dvec3> positions;
  std::vector<std::vector<int>> faces;
  const std::vector<glm::dvec3> out = {{1, 0, 0}, {0, 1, 0}, {-1, -1, 0}};
  for (int sheet = 0; sheet < 3; ++sheet) {
    const int first = int(positions.size());
    const double length = sheet == 0 ? 2.0 : 1.0;
    positions.insert(positions.end(),
                     {{0, 0, 0}, {0, 0, 1}, glm::dvec3(0, 0, 1) + length * out[sheet], length * out[sheet]});
    faces.push_back({first, first + 1, first + 2, first + 3});
  }
  const LoadedSurface loaded = make_surface(positions, faces, "fins");
  EXPECT_EQ(loaded.mesh.face_count(), 2);
  EXPECT_EQ(loaded.dropped_components, 2);
  for (const std::string& warning : loaded.warnings) EXPECT_FALSE(Contains(warning, "joined")) << warning;
  expect_valid_surface(loaded.mesh);
}

TEST_F(MeshLoaderTest, MoebiusStripIsRefused) {
  const int n = 12;
  std::vector<glm::dvec3> positions;
  for (int i = 0; i < n; ++i) {
    const double angle = 2 * std::numbers::pi * i / n, twist = angle / 2;
    const glm::dvec3 centre(3 * std::cos(angle), 3 * std::sin(angle), 0);
    const glm::dvec3 across = std::cos(twist) * glm::dvec3(std::cos(angle), std::sin(angle), 0) +
                              std::sin(twist) * glm::dvec3(0, 0, 1);
    positions.push_back(centre + across);  // top i: 2i
    positions.push_back(centre - across);  // bottom i: 2i + 1
  }
  std::vector<std::vector<int>> faces;
  for (int i = 0; i + 1 < n; ++i) faces.push_back({2 * i, 2 * i + 1, 2 * i + 3, 2 * i + 2});
  faces.push_back({2 * (n - 1), 2 * (n - 1) + 1, 0, 1});  // the half twist joins top to bottom
  const std::string message = error_of([&] { make_surface(positions, faces, "moebius"); });
  EXPECT_TRUE(Contains(message, "not orientable"));
}

TEST_F(MeshLoaderTest, ClosedTetrahedronLoadsWithNoBoundaryLoop) {
  // A closed surface without handles is accepted: the map stage cuts it into charts.
  const LoadedSurface tet =
      load_surface(write("tet.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n"));
  EXPECT_EQ(tet.mesh.face_count(), 4);
  EXPECT_TRUE(tet.mesh.boundary_loops.empty());
}

TEST_F(MeshLoaderTest, ClosedCubeLoadsWithNoBoundaryLoop) {
  const LoadedSurface cube = load_surface(write("cube.off",
                                                "OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
                                                "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n"));
  EXPECT_EQ(cube.mesh.face_count(), 12);
  EXPECT_TRUE(cube.mesh.boundary_loops.empty());
}

TEST_F(MeshLoaderTest, HolesAreLoadedAsLoops) {
  // A 5 x 5 quad grid with two interior quads removed: the outer loop and two holes.
  std::ostringstream obj;
  const int n = 5;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) obj << "v " << i << ' ' << j << " 0\n";
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if ((i == 1 && j == 1) || (i == 3 && j == 3)) continue;
      const int a = j * (n + 1) + i + 1, b = a + 1, c = a + n + 1, d = c + 1;
      obj << "f " << a << ' ' << b << ' ' << d << ' ' << c << '\n';
    }
  const LoadedSurface loaded = load_surface(write("holes.obj", obj.str()));
  ASSERT_EQ(loaded.mesh.boundary_loops.size(), 3u);
  EXPECT_EQ(loaded.mesh.hole_count(), 2);
  EXPECT_EQ(loaded.mesh.outer_loop().size(), 20u) << "the grid's rim is the outer loop";
  EXPECT_EQ(loaded.mesh.boundary_loops[1].size(), 4u);
  EXPECT_EQ(loaded.mesh.boundary_loops[2].size(), 4u);
  expect_valid_surface(loaded.mesh);
}

TEST_F(MeshLoaderTest, HandleIsRefused) {
  // A torus grid with one quad removed: one boundary loop, but genus 1.
  const int n = 8, m = 6;
  std::vector<glm::dvec3> positions;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) {
      const double u = 2 * std::numbers::pi * i / n, v = 2 * std::numbers::pi * j / m;
      positions.emplace_back((3 + std::cos(v)) * std::cos(u), (3 + std::cos(v)) * std::sin(u), std::sin(v));
    }
  std::vector<std::vector<int>> faces;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i)
      if (i != 0 || j != 0)
        faces.push_back({j * n + i, j * n + (i + 1) % n, ((j + 1) % m) * n + (i + 1) % n, ((j + 1) % m) * n + i});
  const std::string message = error_of([&] { make_surface(positions, faces, "torus"); });
  EXPECT_TRUE(Contains(message, "1 handle"));
}

}  // namespace
}  // namespace paver

namespace paver {
namespace {

// One vertex far away used to make every ordinary face "degenerate" (the threshold came from the
// whole bounding box alone): a face is now degenerate only relative to its own size too.
TEST(MeshLoaderRepairs, AFarVertexDoesNotMakeOrdinaryFacesDegenerate) {
  std::vector<glm::dvec3> positions;
  std::vector<std::vector<int>> faces;
  const int n = 10;
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x) positions.push_back({double(x), double(y), 0.0});
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const int a = y * (n + 1) + x;
      faces.push_back({a, a + 1, a + n + 2});
      faces.push_back({a, a + n + 2, a + n + 1});
    }
  positions[n] = {1e7, 0.0, 0.0};  // a corner pulled far out
  const LoadedSurface loaded = make_surface(positions, faces, "far.obj");
  EXPECT_EQ(loaded.dropped_degenerate_faces, 0);
  EXPECT_EQ(loaded.mesh.face_count(), 2 * n * n);
  // A true sliver (area far below its own longest edge squared) is still dropped.
  std::vector<glm::dvec3> sliver = {{0, 0, 0}, {1, 0, 0}, {2, 1e-14, 0}, {0, 1, 0}};
  const LoadedSurface kept = make_surface(sliver, {{0, 1, 3}, {0, 1, 2}, {1, 2, 3}}, "sliver.obj");
  EXPECT_EQ(kept.dropped_degenerate_faces, 1);
}

}  // namespace
}  // namespace paver
