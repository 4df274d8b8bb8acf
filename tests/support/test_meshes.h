#pragma once
// Shared fixtures: the bundled surfaces, the real scanned meshes (assets/scanned), and small meshes
// made in code.
#include "mesh/mesh_loader.h"
#include "mesh/surface_mesh.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <utility>
#include <string>
#include <vector>

namespace paver::test {

inline std::filesystem::path source_dir() { return PAVER_SOURCE_DIR; }

inline std::vector<std::string> bundled_surface_names() {
  return {"dome",   "saddle",    "wave",           "vase",           "torus_section", "pendant",
          "facade", "bangle", "ring_band", "vase_band", "facade_windows", "pendant_pierced"};
}
// Real scans copied into assets/scanned (sources and licence in its README).
inline std::vector<std::string> scanned_mesh_names() {
  return {"bunnyhead", "maze", "bunnyhead_band", "bunnyhead_three_loops"};
}

// The bundled and scanned surfaces that are not disks: bands and surfaces with holes.
inline std::vector<std::string> holed_surface_names() {
  return {"bangle",          "ring_band",      "vase_band",
          "facade_windows",  "pendant_pierced", "bunnyhead_band", "bunnyhead_three_loops"};
}

// Bundled closed surfaces (no boundary loop): the map cuts them into charts.
inline std::vector<std::string> closed_surface_names() { return {"bead"}; }

inline std::filesystem::path bundled_surface(const std::string& name) {
  return source_dir() / "assets/surfaces" / (name + ".obj");
}
inline std::filesystem::path scanned_mesh(const std::string& name) {
  return source_dir() / "assets/scanned" / (name + ".obj");
}

// A flat sheet of nu x nv quads over [0,1]^2 with the quads inside each of `windows` (min and
// max corners in [0,1]^2) left out, mapped through `f(u, v)` to 3D: a wall with windows.
template <class F>
SurfaceMesh sheet_with_windows(int nu, int nv, const std::vector<std::pair<glm::dvec2, glm::dvec2>>& windows, F&& f) {
  std::vector<glm::dvec3> positions;
  std::vector<std::vector<int>> faces;
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) positions.push_back(f(double(i) / nu, double(j) / nv));
  auto id = [&](int i, int j) { return j * (nu + 1) + i; };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const glm::dvec2 middle((i + 0.5) / nu, (j + 0.5) / nv);
      bool open = false;
      for (const auto& [lo, hi] : windows)
        open = open || (middle.x > lo.x && middle.x < hi.x && middle.y > lo.y && middle.y < hi.y);
      if (open) continue;
      faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return make_surface(std::move(positions), faces, "sheet_with_windows").mesh;
}

// A regular triangulated grid of nu x nv quads over [0,1]^2, mapped through `f(u, v)` to 3D.
template <class F>
SurfaceMesh grid_surface(int nu, int nv, F&& f) {
  return sheet_with_windows(nu, nv, {}, std::forward<F>(f));
}

// A band: nu x nv quads over [0,1)^2 closed around u (column nu is column 0), mapped through
// `f(u, v)` to 3D; two boundary loops, at v = 0 and v = 1.
template <class F>
SurfaceMesh band_surface(int nu, int nv, F&& f) {
  std::vector<glm::dvec3> positions;
  std::vector<std::vector<int>> faces;
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i < nu; ++i) positions.push_back(f(double(i) / nu, double(j) / nv));
  auto id = [&](int i, int j) { return j * nu + i % nu; };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return make_surface(std::move(positions), faces, "band_surface").mesh;
}


}  // namespace paver::test

namespace paver::test {

// Midpoint subdivision (each triangle into four): the same geometry with four times the faces.
// Turns the real scanned meshes into 20k+ face test cases without inventing any shape.
inline SurfaceMesh subdivide(const SurfaceMesh& mesh) {
  std::vector<glm::dvec3> positions = mesh.positions;
  std::map<std::pair<int, int>, int> midpoint;
  auto mid = [&](int a, int b) {
    const auto key = std::minmax(a, b);
    const auto [it, added] = midpoint.emplace(key, int(positions.size()));
    if (added) positions.push_back(0.5 * (mesh.positions[a] + mesh.positions[b]));
    return it->second;
  };
  std::vector<std::vector<int>> faces;
  for (const auto& t : mesh.triangles) {
    const int ab = mid(t.x, t.y), bc = mid(t.y, t.z), ca = mid(t.z, t.x);
    faces.push_back({t.x, ab, ca});
    faces.push_back({ab, t.y, bc});
    faces.push_back({ca, bc, t.z});
    faces.push_back({ab, bc, ca});
  }
  return make_surface(std::move(positions), faces, "subdivided").mesh;
}

// A solid ring as a jeweller models one, written as an OBJ with its faces in the groups `outer`,
// `inner`, `top` and `bottom`: a band of radii 10 and 8.5 and height 4 around z, `around` quads
// round and `rows` high on each cylinder.
inline std::string solid_ring_obj(int around = 120, int rows = 8) {
  const double outer = 10, inner = 8.5, half_height = 2;
  std::string obj = "# a solid ring\no ring\n";
  const auto vertex = [&](bool on_outer, int i, int j) {  // 1-based: the outer cylinder's first
    return 1 + (on_outer ? 0 : around * (rows + 1)) + j * around + (i % around);
  };
  for (const double radius : {outer, inner})
    for (int j = 0; j <= rows; ++j)
      for (int i = 0; i < around; ++i) {
        const double a = 2 * 3.14159265358979323846 * i / around;
        obj += "v " + std::to_string(radius * std::cos(a)) + " " + std::to_string(radius * std::sin(a)) + " " +
               std::to_string(-half_height + 2 * half_height * j / rows) + "\n";
      }
  const auto face = [&](int a, int b, int c, int d) {
    obj += "f " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(c) + " " + std::to_string(d) + "\n";
  };
  obj += "g outer\n";
  for (int i = 0; i < around; ++i)
    for (int j = 0; j < rows; ++j) face(vertex(true, i, j), vertex(true, i + 1, j), vertex(true, i + 1, j + 1), vertex(true, i, j + 1));
  obj += "g inner\n";
  for (int i = 0; i < around; ++i)
    for (int j = 0; j < rows; ++j) face(vertex(false, i, j), vertex(false, i, j + 1), vertex(false, i + 1, j + 1), vertex(false, i + 1, j));
  obj += "g top\n";
  for (int i = 0; i < around; ++i) face(vertex(true, i, rows), vertex(true, i + 1, rows), vertex(false, i + 1, rows), vertex(false, i, rows));
  obj += "g bottom\n";
  for (int i = 0; i < around; ++i) face(vertex(true, i, 0), vertex(false, i, 0), vertex(false, i + 1, 0), vertex(true, i + 1, 0));
  return obj;
}

}  // namespace paver::test
