// Engine II benchmarks, JSON with --benchmark_format=json:
//   design/<name>       the whole pavement (pattern, optimizer, post-processing, collision
//                       resolution, quality) per bundled design; stage times as counters.
//   solver/<N>/<threads> CPU solver milliseconds per iteration at N particles on the dense wave.
//   solver_shape/<band|disk>/<N>/<threads> the same on the bangle's seamless map (which wraps) and on the dome
//                       (a disk), at N particles of a tri lattice: a band costs what a disk costs
//                       per particle (compare ns_per_particle of the two rows of one run).
#include "core/stopwatch.h"
#include "io/design_io.h"
#include "mesh/mesh_loader.h"
#include "pipeline/pavement.h"
#include "pipeline/run_pipeline.h"
#include "solver/spring_solver.h"

#include "bundled_designs.h"

#include <benchmark/benchmark.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <string>

namespace {

namespace fs = std::filesystem;

// design name without ".json" -> surface file.
std::map<std::string, std::string> design_surfaces() {
  std::map<std::string, std::string> out;
  for (const auto& [design, surface] : paver::test::bundled_design_surfaces(PAVER_SOURCE_DIR))
    out[design.substr(0, design.size() - 5)] = surface;
  return out;
}

void design(benchmark::State& state, std::string name, std::string surface) {
  const paver::Stopwatch watch;
  const auto map = std::make_shared<const paver::SurfaceMap>(
      paver::build_surface_map(paver::load_surface(fs::path(PAVER_SOURCE_DIR) / "assets/surfaces" / surface).mesh));
  const double map_ms = watch.milliseconds();
  paver::PipelineRequest request;
  request.map = map;
  request.design = paver::load_design(fs::path(PAVER_SOURCE_DIR) / "assets/designs" / (name + ".json"));
  paver::Pavement p;
  for (auto _ : state) p = paver::run_pipeline(request).pavement;
  state.counters["load_and_map_ms"] = map_ms;
  for (const auto& [stage, ms] : p.timings) state.counters[stage + "_ms"] = ms;
  state.counters["elements"] = double(p.elements.size());
  state.counters["iterations"] = p.solve.iterations;
  state.counters["converged"] = p.solve.reason == paver::StopReason::Converged;
  state.counters["collisions_initial"] = double(p.before.contact_violations);
  state.counters["collisions_paper"] = double(p.paper.contact_violations);
  state.counters["collisions_final"] = double(p.after.contact_violations);
  state.counters["removed"] = p.resolution.removed;
  state.counters["nn_p5"] = p.after.neighbor_ratio.p5;
  state.counters["nn_median"] = p.after.neighbor_ratio.median;
}

// The dense wave (100k faces) with a hexagonal pattern of about n particles.
struct SolverCase {
  paver::SurfaceMap map;
  paver::SolverSurface surface;
  paver::Pattern pattern;
  double spacing = 1;
};

const SolverCase& solver_case(int n) {
  static std::map<int, std::unique_ptr<SolverCase>> cases;
  auto& c = cases[n];
  if (!c) {
    static const paver::SurfaceMap map =
        paver::build_surface_map(paver::load_surface(fs::path(PAVER_BINARY_DIR) / "assets/wave_dense.obj").mesh);
    c = std::make_unique<SolverCase>();
    c->map = map;
    c->surface = paver::make_solver_surface(map);
    // Hexagonal lattice: 2 points per cell of area 3 sqrt(3) / 2 D^2.
    c->spacing = std::sqrt(paver::surface_area(map.mesh) * 2 / (1.5 * std::sqrt(3.0)) / n);
    paver::PatternDesign pd;
    pd.tessellation = paver::Tessellation::Hexagon;
    pd.spacing = c->spacing;
    c->pattern = paver::build_pattern(map, paver::make_design_cell(pd), {});
  }
  return *c;
}

// A tri lattice of about n particles on a bundled surface, laid out (not optimised) as the
// pipeline does: on the bangle, on its seamless map.
struct ShapeCase {
  std::shared_ptr<const paver::SurfaceMap> map;
  paver::Pavement pavement;
  paver::SolverSurface surface;
};

const ShapeCase& shape_case(const std::string& surface, int n) {
  static std::map<std::pair<std::string, int>, std::unique_ptr<ShapeCase>> cases;
  auto& c = cases[{surface, n}];
  if (!c) {
    c = std::make_unique<ShapeCase>();
    c->map = std::make_shared<const paver::SurfaceMap>(paver::build_surface_map(
        paver::load_surface(fs::path(PAVER_SOURCE_DIR) / "assets/surfaces" / (surface + ".obj")).mesh));
    paver::Design design;
    design.pattern.topology = paver::Topology::Lattice;
    design.pattern.tessellation = paver::Tessellation::Triangle;
    design.pattern.spacing = std::sqrt(2 * paver::surface_area(c->map->mesh) / (std::sqrt(3.0) * n));
    paver::PavementOptions options;
    options.optimize = false;
    options.postprocess = false;
    options.refill = false;
    c->pavement = paver::make_pavement(*c->map, design, options);
    c->surface = paver::make_solver_surface(paver::pavement_map(*c->map, c->pavement));
  }
  return *c;
}

void solver_shape(benchmark::State& state, std::string surface) {
  const ShapeCase& c = shape_case(surface, int(state.range(0)));
  paver::SpringSystem system = paver::make_spring_system(c.pavement.pattern);
  paver::SolverParams params;
  const int threads = state.range(1) > 0 ? int(state.range(1)) : tbb::this_task_arena::max_concurrency();
  paver::CpuSpringSolver s(c.surface, system, params, c.pavement.design.pattern.spacing, threads);
  for (auto _ : state) benchmark::DoNotOptimize(s.step());
  state.counters["particles"] = system.particle_count();
  state.counters["threads"] = threads;
  state.counters["seamless"] = c.pavement.seamless;
  state.counters["ns_per_particle"] = benchmark::Counter(
      double(state.iterations()) * system.particle_count(), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void solver(benchmark::State& state) {
  const SolverCase& c = solver_case(int(state.range(0)));
  const int threads = state.range(1) > 0 ? int(state.range(1)) : tbb::this_task_arena::max_concurrency();
  paver::SpringSystem system = paver::make_spring_system(c.pattern);
  paver::SolverParams params;
  paver::CpuSpringSolver s(c.surface, system, params, c.spacing, threads);
  for (auto _ : state) benchmark::DoNotOptimize(s.step());
  state.counters["particles"] = system.particle_count();
  state.counters["springs"] = system.spring_count();
  state.counters["threads"] = threads;
  state.counters["iterations_per_second"] = benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}

const bool registered = [] {
  for (const auto& [name, surface] : design_surfaces())
    benchmark::RegisterBenchmark(("design/" + name).c_str(), design, name, surface)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->Iterations(3);
  for (const auto& [name, surface] : {std::pair{"band", "bangle"}, std::pair{"disk", "dome"}})
    benchmark::RegisterBenchmark(("solver_shape/" + std::string(name)).c_str(), solver_shape, std::string(surface))
        ->ArgsProduct({{100000}, {1, 0}})
        ->ArgNames({"particles", "threads"})
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
  if (fs::exists(fs::path(PAVER_BINARY_DIR) / "assets/wave_dense.obj"))
    benchmark::RegisterBenchmark("solver", solver)
        ->ArgsProduct({{1000, 10000, 100000, 1000000}, {1, 0}})
        ->ArgNames({"particles", "threads"})
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
  return true;
}();

}  // namespace

BENCHMARK_MAIN();
