// Our bijective map against CGAL's ARAP parameterizer on the same meshes in the same run (issue
// 13 asks for 10x): `parameterize_surface` (what `paver param` and `paver run` use: symmetric
// Dirichlet; paver_arap: the paper's ARAP energy) and CGAL's ARAP_parameterizer_3 with its
// defaults and no post-processing, on the scanned bunny head and on it split 1 -> 4 once and
// twice (12k and 48k faces; the shape stays the scan's). Counters: faces, flipped triangles
// (CGAL's map may come out mirrored: the minority orientation counts), iterations,
// factorizations and distortion (ours). Run: build/bin/paver-map-bench --benchmark_format=json
#include "map/bijective_map.h"
#include "mesh/mesh_loader.h"

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/ARAP_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <benchmark/benchmark.h>

#include <filesystem>
#include <map>
#include <string>
#include <utility>

namespace paver {
namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using CgalMesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace SMP = CGAL::Surface_mesh_parameterization;

// Each triangle split into four at its edge midpoints (shared midpoints, so the mesh stays
// manifold and keeps its one boundary loop).
SurfaceMesh split_four(const SurfaceMesh& m) {
  SurfaceMesh out;
  out.positions = m.positions;
  std::map<std::pair<int, int>, int> midpoint;
  const auto mid = [&](int a, int b) {
    const auto key = std::minmax(a, b);
    const auto [it, added] = midpoint.try_emplace(key, int(out.positions.size()));
    if (added) out.positions.push_back(0.5 * (m.positions[a] + m.positions[b]));
    return it->second;
  };
  std::vector<std::vector<int>> faces;
  for (const glm::ivec3& t : m.triangles) {
    const int ab = mid(t.x, t.y), bc = mid(t.y, t.z), ca = mid(t.z, t.x);
    faces.push_back({t.x, ab, ca});
    faces.push_back({ab, t.y, bc});
    faces.push_back({ca, bc, t.z});
    faces.push_back({ab, bc, ca});
  }
  return make_surface(out.positions, faces, "split").mesh;
}

SurfaceMesh head(int splits) {
  SurfaceMesh mesh = load_surface(std::filesystem::path(PAVER_SOURCE_DIR) / "assets/scanned/bunnyhead.obj").mesh;
  for (int k = 0; k < splits; ++k) mesh = split_four(mesh);
  return mesh;
}

template <class Uv>
long flipped(const std::vector<glm::ivec3>& triangles, const Uv& uv_of) {
  long positive = 0, negative = 0;
  for (const glm::ivec3& t : triangles) {
    const glm::dvec2 a = uv_of(t.x), b = uv_of(t.y), c = uv_of(t.z);
    const double area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    (area > 0 ? positive : negative) += 1;
  }
  return std::min(positive, negative);
}

void ours(benchmark::State& state, int splits, MapEnergy energy) {
  const SurfaceMesh mesh = head(splits);
  MapOptions options;
  options.energy = energy;
  Parameterization p;
  for (auto _ : state) {
    p = parameterize_surface(mesh, options);
    benchmark::DoNotOptimize(p.uv.data());
  }
  state.counters["faces"] = mesh.face_count();
  state.counters["flipped"] = double(flipped(mesh.triangles, [&](int v) { return p.uv[v]; }));
  state.counters["iterations"] = p.report.iterations;
  state.counters["factorizations"] = p.report.factorizations;
  state.counters["stretch_mean"] = p.quality.stretch_mean;
  state.counters["area_distortion_mean"] = p.quality.area_distortion_mean;
}

void cgal_arap(benchmark::State& state, int splits) {
  const SurfaceMesh mesh = head(splits);
  CgalMesh cgal;
  std::vector<CgalMesh::Vertex_index> vertex;
  for (const glm::dvec3& p : mesh.positions) vertex.push_back(cgal.add_vertex({p.x, p.y, p.z}));
  for (const glm::ivec3& t : mesh.triangles) cgal.add_face(vertex[t.x], vertex[t.y], vertex[t.z]);
  const auto border = CGAL::Polygon_mesh_processing::longest_border(cgal).first;
  auto uv = cgal.add_property_map<CgalMesh::Vertex_index, Kernel::Point_2>("v:uv").first;
  SMP::Error_code error = SMP::OK;
  for (auto _ : state) {
    error = SMP::parameterize(cgal, SMP::ARAP_parameterizer_3<CgalMesh>(), border, uv);
    benchmark::DoNotOptimize(error);
  }
  if (error != SMP::OK) state.SkipWithError(SMP::get_error_message(error));
  state.counters["faces"] = mesh.face_count();
  state.counters["flipped"] = double(flipped(mesh.triangles, [&](int v) {
    const Kernel::Point_2 q = get(uv, vertex[v]);
    return glm::dvec2(q.x(), q.y());
  }));
}

const bool registered = [] {
  for (int splits : {0, 1, 2}) {
    const std::string size = std::to_string(3000 << (2 * splits));
    benchmark::RegisterBenchmark(("map/paver/bunnyhead_" + size).c_str(), ours, splits, MapEnergy::SymmetricDirichlet)
        ->UseRealTime()->Unit(benchmark::kMillisecond)->Iterations(1);
    benchmark::RegisterBenchmark(("map/paver_arap/bunnyhead_" + size).c_str(), ours, splits, MapEnergy::Arap)
        ->UseRealTime()->Unit(benchmark::kMillisecond)->Iterations(1);
    benchmark::RegisterBenchmark(("map/cgal_arap/bunnyhead_" + size).c_str(), cgal_arap, splits)
        ->UseRealTime()->Unit(benchmark::kMillisecond)->Iterations(1);
  }
  return true;
}();

}  // namespace
}  // namespace paver

BENCHMARK_MAIN();
