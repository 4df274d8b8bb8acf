// Engine benchmarks: parameterization time and distortion per asset, lifting throughput, the
// whole pipeline (load, map, pattern, optimize, measure; no export) on the bunny head with the
// default designs, lattice and adaptive (issue 10 asks for under 2 s on 2 cores), and each output
// file written for 10k and 100k gems (issue 44 asks about a second per 100k stones for them all).
// JSON: build/bin/paver-bench --benchmark_format=json
#include "map/bijective_map.h"
#include "map/lifting.h"
#include "mesh/mesh_loader.h"
#include "map/surface_map.h"
#include "io/element_export.h"
#include "io/gltf_export.h"
#include "io/threemf_export.h"
#include "pipeline/run_pipeline.h"

#include <benchmark/benchmark.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <filesystem>
#include <unistd.h>
#include <random>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

std::vector<fs::path> bench_surfaces() {
  std::vector<fs::path> paths;
  for (const char* name : {"dome", "saddle", "wave", "vase", "torus_section", "pendant", "facade"})
    paths.push_back(fs::path(PAVER_SOURCE_DIR) / "assets/surfaces" / (std::string(name) + ".obj"));
  for (const char* name : {"bunnyhead", "maze"})
    paths.push_back(fs::path(PAVER_SOURCE_DIR) / "assets/scanned" / (std::string(name) + ".obj"));
  for (const char* name : {"dome_dense", "wave_dense", "facade_dense"})
    paths.push_back(fs::path(PAVER_BINARY_DIR) / "assets" / (std::string(name) + ".obj"));
  std::erase_if(paths, [](const fs::path& p) { return !fs::exists(p); });
  return paths;
}

void parameterize(benchmark::State& state, fs::path path) {
  const paver::SurfaceMesh mesh = paver::load_surface(path).mesh;
  paver::Parameterization p;
  for (auto _ : state) {
    p = paver::parameterize_surface(mesh, paver::map_options_for(mesh));
    benchmark::DoNotOptimize(p.uv.data());
  }
  state.counters["faces"] = mesh.face_count();
  state.counters["iterations"] = p.report.iterations;
  state.counters["flipped"] = p.quality.flipped_triangles;
  state.counters["boundary_overlaps"] = p.quality.boundary_intersections;
  state.counters["stretch_mean"] = p.quality.stretch_mean;
  state.counters["stretch_max"] = p.quality.stretch_max;
  state.counters["area_distortion_mean"] = p.quality.area_distortion_mean;
}

void lift(benchmark::State& state, fs::path path) {
  const paver::SurfaceMap map = paver::build_surface_map(paver::load_surface(path).mesh);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(map.uv_min.x, map.uv_max.x), v(map.uv_min.y, map.uv_max.y);
  std::vector<glm::dvec2> points(state.range(0));
  for (auto& p : points) p = {u(rng), v(rng)};
  paver::LiftedPoints out;
  out.resize(points.size());
  for (auto _ : state) {
    benchmark::DoNotOptimize(paver::lift_points(map, points, out));
  }
  state.SetItemsProcessed(state.iterations() * int64_t(points.size()));
  state.counters["faces"] = map.mesh.face_count();
}

void pave(benchmark::State& state, fs::path path, paver::Tessellation tessellation, paver::Topology topology) {
  paver::PipelineRequest request;
  request.surface_path = path;
  request.design.pattern.tessellation = tessellation;
  request.design.pattern.topology = topology;
  paver::PipelineResult result;
  for (auto _ : state) {
    result = paver::run_pipeline(request);
    benchmark::DoNotOptimize(result.pavement.elements.size());
  }
  const paver::PavementQuality& q = result.pavement.after;
  state.counters["elements"] = double(q.elements);
  state.counters["fill"] = q.fill;
  state.counters["nn_p95"] = q.neighbor_ratio.p95;
  state.counters["nn_cv"] = q.neighbor_ratio.cv;
  state.counters["regular_valence"] = q.regular_valence_share;
  state.counters["violations"] = double(q.contact_violations);
}

// `count` gems in rows on a gently domed sheet, as a pavement's export sees them.
paver::Elements gem_rows(std::size_t count) {
  paver::Elements e;
  e.reserve(count);
  const std::size_t side = std::size_t(std::ceil(std::sqrt(double(count))));
  for (std::size_t i = 0; i < count; ++i) {
    const double x = 1.1 * double(i % side), y = 1.1 * double(i / side);
    const glm::dvec3 normal = glm::normalize(glm::dvec3(-0.001 * x, -0.001 * y, 1));
    e.push_back(paver::ElementKind::Vertex, int(i), 0, {x, y}, {x, y, 0.0005 * (x * x + y * y)}, normal, 1.0,
                paver::ShapeKind::Gem);
    e.id.back() = int(i);
  }
  return e;
}

// One output file of `count` gems, written again and again into a scratch folder.
template <class Write>
void export_file(benchmark::State& state, std::string name, Write write) {
  const paver::Elements elements = gem_rows(std::size_t(state.range(0)));
  const fs::path folder = fs::temp_directory_path() / ("paver-export-bench-" + std::to_string(::getpid()));
  fs::create_directories(folder);
  const fs::path path = folder / name;
  for (auto _ : state) write(path, elements);
  state.counters["bytes"] = double(fs::file_size(path));
  state.SetItemsProcessed(state.iterations() * state.range(0));  // stones per second
  fs::remove_all(folder);
}

void register_exports() {
  using paver::Elements;
  const auto put = [](const char* name, auto write) {
    benchmark::RegisterBenchmark((std::string("export/") + name).c_str(),
                                 [name, write](benchmark::State& state) { export_file(state, name, write); })
        ->Arg(10000)->Arg(100000)->UseRealTime()->Unit(benchmark::kMillisecond);
  };
  put("placements.csv", [](const fs::path& p, const Elements& e) { paver::write_placements_csv(p, e); });
  put("elements.ply", [](const fs::path& p, const Elements& e) { paver::write_elements_ply(p, e); });
  put("elements.obj", [](const fs::path& p, const Elements& e) { paver::write_elements_obj(p, e); });
  put("elements.stl", [](const fs::path& p, const Elements& e) { paver::write_elements_stl(p, e); });
  put("elements.glb", [](const fs::path& p, const Elements& e) { paver::write_pavement_glb(p, {}, e, paver::Units::Millimetre); });
  put("paved.3mf", [](const fs::path& p, const Elements& e) { paver::write_pavement_3mf(p, nullptr, e, paver::Units::Millimetre); });
}

const bool registered = [] {
  register_exports();
  const fs::path head = fs::path(PAVER_SOURCE_DIR) / "assets/scanned/bunnyhead.obj";
  for (const auto tessellation : {paver::Tessellation::Triangle, paver::Tessellation::Hexagon})
    for (const auto topology : {paver::Topology::Lattice, paver::Topology::Adaptive})
      benchmark::RegisterBenchmark(("pave/bunnyhead/" + std::string(paver::enum_name(tessellation)) + "/" +
                                    std::string(paver::enum_name(topology)))
                                       .c_str(),
                                   pave, head, tessellation, topology)
          ->UseRealTime()->Unit(benchmark::kMillisecond)->Iterations(3);
  for (const auto& path : bench_surfaces())
    benchmark::RegisterBenchmark(("parameterize/" + path.stem().string()).c_str(), parameterize, path)
        ->UseRealTime()->Unit(benchmark::kMillisecond);
  for (const char* name : {"dome", "wave_dense"}) {
    fs::path path = fs::path(PAVER_SOURCE_DIR) / "assets/surfaces" / (std::string(name) + ".obj");
    if (!fs::exists(path)) path = fs::path(PAVER_BINARY_DIR) / "assets" / (std::string(name) + ".obj");
    if (fs::exists(path))
      benchmark::RegisterBenchmark(("lift/" + std::string(name)).c_str(), lift, path)
          ->Arg(100000)->UseRealTime()->Unit(benchmark::kMillisecond);
  }
  return true;
}();

}  // namespace

BENCHMARK_MAIN();
