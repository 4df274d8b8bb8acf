// Tests for engine/io/uv_map_export.cpp: the OBJ written for a map has one `v` per mesh vertex (its
// position), one `vt` per vertex (its uv, to 9 significant digits), one `f a/a b/b c/c` per
// triangle with the mesh's 1-based indices in the mesh's order, nothing else but the header
// comment, and no temporary file left beside it; it reads back as the same surface.
#include "io/uv_map_export.h"

#include "map/surface_map.h"
#include "mesh/mesh_loader.h"
#include "surface_maps.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace paver {
namespace {

namespace fs = std::filesystem;

class UvMapExport : public ::testing::Test {
protected:
  void SetUp() override {
    folder_ = fs::temp_directory_path() /
              ("paver_uv_map_export_" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(folder_);
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }

  fs::path folder_;
};

struct Obj {
  std::string header;
  std::vector<glm::dvec3> v;
  std::vector<glm::dvec2> vt;
  std::vector<glm::ivec3> f_position, f_texture;
  std::vector<std::string> other;  // any other line
};

Obj read_obj(const fs::path& path) {
  Obj obj;
  std::ifstream in(path);
  std::string line;
  bool first = true;
  while (std::getline(in, line)) {
    if (first) {
      obj.header = line, first = false;
      continue;
    }
    std::istringstream words(line);
    std::string tag;
    words >> tag;
    if (tag == "v") {
      glm::dvec3 p;
      words >> p.x >> p.y >> p.z;
      obj.v.push_back(p);
    } else if (tag == "vt") {
      glm::dvec2 q;
      words >> q.x >> q.y;
      obj.vt.push_back(q);
    } else if (tag == "f") {
      glm::ivec3 p, t;
      char slash1, slash2, slash3;
      words >> p.x >> slash1 >> t.x >> p.y >> slash2 >> t.y >> p.z >> slash3 >> t.z;
      if (slash1 != '/' || slash2 != '/' || slash3 != '/') obj.other.push_back(line);
      obj.f_position.push_back(p);
      obj.f_texture.push_back(t);
    } else {
      obj.other.push_back(line);
    }
    std::string rest;
    if (words >> rest) obj.other.push_back(line);  // more numbers than the line should have
  }
  return obj;
}

// Within the 9 significant digits written.
::testing::AssertionResult close(double got, double want) {
  if (std::abs(got - want) <= 1e-8 * std::max(std::abs(want), 1e-300) + 1e-300) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << got << " is not " << want;
}

void expect_matches(const Obj& obj, const SurfaceMesh& mesh, const std::vector<glm::dvec2>& uv) {
  EXPECT_TRUE(obj.other.empty()) << "unexpected line: " << obj.other.front();
  ASSERT_EQ(obj.v.size(), size_t(mesh.vertex_count()));
  ASSERT_EQ(obj.vt.size(), uv.size());
  ASSERT_EQ(obj.f_position.size(), size_t(mesh.face_count()));
  for (int i = 0; i < mesh.vertex_count(); ++i) {
    for (int k = 0; k < 3; ++k) EXPECT_TRUE(close(obj.v[i][k], mesh.positions[i][k])) << "v " << i;
  }
  for (size_t i = 0; i < uv.size(); ++i) {
    EXPECT_TRUE(close(obj.vt[i].x, uv[i].x)) << "vt " << i;
    EXPECT_TRUE(close(obj.vt[i].y, uv[i].y)) << "vt " << i;
  }
  for (int t = 0; t < mesh.face_count(); ++t) {
    EXPECT_EQ(obj.f_position[t], mesh.triangles[t] + 1) << "f " << t;
    EXPECT_EQ(obj.f_texture[t], mesh.triangles[t] + 1) << "f " << t << ": vt index differs from v index";
  }
}

TEST_F(UvMapExport, ThePendantsMapIsWrittenVertexForVertex) {
  const SurfaceMap& map = *test::bundled_map("pendant");
  const fs::path path = folder_ / "map.obj";
  write_uv_map_obj(path, map.mesh, map.uv);

  const Obj obj = read_obj(path);
  EXPECT_EQ(obj.header, "# paver parameterization: " + std::to_string(map.mesh.vertex_count()) + " vertices, " +
                            std::to_string(map.mesh.face_count()) + " faces; vt is the 2D map, its area equals the surface's");
  expect_matches(obj, map.mesh, map.uv);

  // Only the file itself is left in the folder (the atomic write's temporary is gone).
  int files = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(folder_)) ++files;
  EXPECT_EQ(files, 1);

  // It reads back as the same surface: vertices and triangles unchanged.
  const SurfaceMesh back = load_surface(path).mesh;
  ASSERT_EQ(back.vertex_count(), map.mesh.vertex_count());
  ASSERT_EQ(back.face_count(), map.mesh.face_count());
  for (int t = 0; t < back.face_count(); ++t) EXPECT_EQ(back.triangles[t], map.mesh.triangles[t]) << t;
}

TEST_F(UvMapExport, AwkwardNumbersKeepNineDigits) {
  // Two triangles with coordinates and uv of every magnitude and sign.
  SurfaceMesh mesh;
  mesh.positions = {{0, 0, 0}, {1.0 / 3, -2e-7, 12345.678901}, {-1e5, 0.5, 2}, {3.14159265358979, 1e-300, -7}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  mesh.boundary_loops = {{0, 1, 2, 3}};
  const std::vector<glm::dvec2> uv = {{0, 0}, {2.0 / 3, 1e-12}, {-98765.4321, 0.1}, {1e10, -1.0 / 7}};
  const fs::path path = folder_ / "awkward.obj";
  write_uv_map_obj(path, mesh, uv);
  expect_matches(read_obj(path), mesh, uv);
}

TEST_F(UvMapExport, RewritingReplacesTheFile) {
  SurfaceMesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.triangles = {{0, 1, 2}};
  mesh.boundary_loops = {{0, 1, 2}};
  const fs::path path = folder_ / "map.obj";
  write_uv_map_obj(path, mesh, {{0, 0}, {5, 0}, {0, 5}});
  write_uv_map_obj(path, mesh, {{0, 0}, {1, 0}, {0, 1}});
  const Obj obj = read_obj(path);
  expect_matches(obj, mesh, {{0, 0}, {1, 0}, {0, 1}});
}

}  // namespace
}  // namespace paver
