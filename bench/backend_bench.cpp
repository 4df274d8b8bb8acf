// paver-backend-bench: the solver on every backend in one run, so ratios compare like with like.
//   ms per iteration and iterations/s at 1k, 10k, 100k and 1M particles (hexagonal pattern on the
//   dense wave, 100k faces) for the CPU with one thread, the CPU with all threads, and Vulkan on
//   every device found; and the end-to-end pavement time of each bundled design per backend,
//   with `auto` (the CLI's routing by size) beside them when there is a GPU. `--sweep 100,400,..`
//   adds the whole pavement of the torus design at about those particle counts, to see where a
//   GPU starts to pay (kAutoGpuLeastParticles).
// Prints a table (with GPU/CPU ratios) and writes JSON: paver-backend-bench [--json FILE]
//   [--sizes 1000,10000] [--skip-designs] [--skip-cpu] [--sweep 100,200,400]
#include "paver/compute/vulkan_context.h"
#include "paver/compute/vulkan_spring_solver.h"
#include "backend_choice.h"
#include "io/atomic_file.h"
#include "io/design_io.h"
#include "mesh/mesh_loader.h"
#include "pipeline/run_pipeline.h"
#include "solver/spring_solver.h"

#include "bundled_designs.h"

#include <nlohmann/json.hpp>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct Backend {
  std::string name;  // "cpu 1 thread", "cpu 2 threads", "vulkan: <device>"
  paver::SolverFactory factory;
  bool gpu = false;
};

double seconds_of(const std::function<void()>& f) {
  const auto t0 = Clock::now();
  f();
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Per-iteration time: (time of 1 + m iterations - time of 1 iteration) / m, best of 3, so
// uploads, initialisation and read-back are not counted. m grows tenfold until the m iterations
// take a tenth of a second: a real GPU runs thousands a second, and a difference of a few
// iterations would be lost in the noise of the uploads.
double ms_per_iteration(const Backend& b, const paver::SolverSurface& surface, const paver::Pattern& pattern,
                        double spacing, int m, int* iterations_timed) {
  auto solve = [&](int iterations) {
    paver::SpringSystem system = paver::make_spring_system(pattern);
    paver::SolverParams params;
    params.iterations = iterations;
    params.threshold = 0;  // run them all
    auto solver = b.factory(surface, system, params, spacing);
    return seconds_of([&] { solver->solve(); });
  };
  constexpr double kEnoughSeconds = 0.1;
  constexpr int kMostIterations = 100000;
  // First use at this size grows the backend's buffers (the GPU's staging memory too): not timed,
  // or the first difference below is off by the growth and picks too few iterations.
  solve(1);
  const auto difference = [&] {
    const double many = solve(1 + m);
    const double one = solve(1);
    return many - one;
  };
  while (m < kMostIterations && difference() < kEnoughSeconds) m = std::min(kMostIterations, m * 10);
  double best = 1e30;
  for (int rep = 0; rep < 3; ++rep) best = std::min(best, difference() / m);
  *iterations_timed = m;
  return 1e3 * std::max(best, 1e-9);
}

// design name without ".json" -> surface file.
std::map<std::string, std::string> design_surfaces() {
  std::map<std::string, std::string> out;
  for (const auto& [design, surface] : paver::test::bundled_design_surfaces(PAVER_SOURCE_DIR))
    out[design.substr(0, design.size() - 5)] = surface;
  return out;
}

std::vector<int> parse_sizes(const std::string& text) {
  std::vector<int> out;
  std::stringstream s(text);
  for (std::string item; std::getline(s, item, ',');) out.push_back(std::stoi(item));
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  std::string json_path;
  std::vector<int> sizes = {1000, 10000, 100000, 1000000};
  std::vector<int> sweep;
  bool designs = true, skip_cpu = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--json" && i + 1 < argc) json_path = argv[++i];
    else if (a == "--sizes" && i + 1 < argc) sizes = parse_sizes(argv[++i]);
    else if (a == "--skip-designs") designs = false;
    else if (a == "--skip-cpu") skip_cpu = true;
    else if (a == "--sweep" && i + 1 < argc) sweep = parse_sizes(argv[++i]);
    else {
      std::fprintf(stderr, "usage: paver-backend-bench [--json FILE] [--sizes 1000,10000,...] [--skip-designs] [--skip-cpu] "
                           "[--sweep 100,200,...]\n");
      return 2;
    }
  }
  const int cores = tbb::this_task_arena::max_concurrency();
  std::vector<Backend> backends = {{"cpu 1 thread", paver::cpu_solver_factory(1), false},
                                   {"cpu " + std::to_string(cores) + " threads", paver::cpu_solver_factory(0), false}};
  nlohmann::json out = {{"cores", cores}, {"devices", nlohmann::json::array()}};
  if (skip_cpu) backends.clear();  // a GPU's figures alone, e.g. two builds alternated on one device
  if (auto devices = paver::gpu::list_devices()) {
    for (const auto& d : devices.value()) {
      out["devices"].push_back({{"name", d.name}, {"type", d.type}, {"vulkan", d.api_version}});
      if (!d.compute) continue;
      paver::gpu::ContextOptions options;
      options.device = d.name;
      auto context = paver::gpu::VulkanContext::create(options);
      if (!context) continue;
      auto session = paver::gpu::VulkanSolverSession::create(context.value());
      if (session) backends.push_back({"vulkan: " + d.name, paver::gpu::vulkan_solver_factory(session.value(), 256), true});
    }
  } else {
    std::printf("no Vulkan: %s\n", devices.error().message.c_str());
  }

  // Per-iteration cost at growing sizes.
  const fs::path dense = fs::path(PAVER_BINARY_DIR) / "assets/wave_dense.obj";
  const paver::SurfaceMap map = paver::build_surface_map(paver::load_surface(dense).mesh);
  const paver::SolverSurface surface = paver::make_solver_surface(map);
  out["iteration"] = nlohmann::json::array();
  std::printf("\nSolver ms per iteration (hexagonal pattern on %s, %d faces)\n", dense.filename().c_str(),
              map.mesh.face_count());
  std::printf("%10s", "particles");
  for (const auto& b : backends) std::printf(" | %28.28s", b.name.c_str());
  const std::size_t first_gpu = skip_cpu ? backends.size() : 2;  // no ratios without the CPU rows
  for (size_t g = first_gpu; g < backends.size(); ++g) std::printf(" | %14s", "GPU/CPU(all)");
  std::printf("\n");
  for (int n : sizes) {
    paver::PatternDesign pd;
    pd.tessellation = paver::Tessellation::Hexagon;
    pd.spacing = std::sqrt(paver::surface_area(map.mesh) * 2 / (1.5 * std::sqrt(3.0)) / n);
    const paver::Pattern pattern = paver::build_pattern(map, paver::make_design_cell(pd), {});
    const int m = std::max(4, std::min(200, 2000000 / std::max(1, pattern.point_count())));
    std::vector<double> ms;
    std::printf("%10d", pattern.point_count());
    for (const auto& b : backends) {
      int timed = 0;
      ms.push_back(ms_per_iteration(b, surface, pattern, pd.spacing, m, &timed));
      std::printf(" | %12.3f ms %9.0f it/s", ms.back(), 1000.0 / ms.back());
      std::fflush(stdout);
      out["iteration"].push_back({{"backend", b.name}, {"particles", pattern.point_count()},
                                  {"springs", pattern.edge_count()}, {"ms_per_iteration", ms.back()},
                                  {"iterations_per_second", 1000.0 / ms.back()}, {"iterations_timed", timed}});
    }
    for (size_t g = first_gpu; g < backends.size(); ++g) {
      std::printf(" | %13.2fx", ms[1] / ms[g]);
      out["iteration"].back()["speedup_over_cpu_all_threads"] = ms[1] / ms[g];
    }
    std::printf("\n");
  }

  // The whole pavement: every backend above, and the CLI's `auto` beside them on a GPU.
  std::vector<Backend> pavers = backends;
  if (backends.size() > (skip_cpu ? 0u : 2u))
    pavers.push_back({"auto (gpu from " + std::to_string(paver::app::kAutoGpuLeastParticles) + ")",
                      paver::app::choose_backend("auto", "", 0).factory, true});
  const auto print_header = [&](const char* first) {
    std::printf("%-26s", first);
    for (const auto& b : pavers) std::printf(" | %28.28s", b.name.c_str());
    std::printf(" | identical\n");
  };
  // Paves `request` with each backend; prints a row and adds one JSON entry per backend to `rows`.
  const auto pave_with_each = [&](paver::PipelineRequest request, const std::string& label, nlohmann::json& rows) {
    std::printf("%-26s", label.c_str());
    std::vector<paver::Elements> results;
    for (const auto& b : pavers) {
      request.pavement.solver = b.factory;
      paver::PipelineResult r;
      const double ms = 1e3 * seconds_of([&] { r = paver::run_pipeline(request); });
      const paver::Pavement& p = r.pavement;
      results.push_back(p.elements);
      std::printf(" | %25.1f ms", ms);
      std::fflush(stdout);
      rows.push_back({{"design", label}, {"backend", b.name}, {"ran_on", p.solve.backend}, {"ms", ms},
                      {"particles", p.points.size()}, {"elements", p.elements.size()},
                      {"iterations", p.solve.iterations}, {"collisions", p.after.contact_violations}});
    }
    bool same = true;
    for (const auto& e : results) same = same && e.position == results.front().position;
    std::printf(" | %s\n", same ? "yes" : "no");
  };
  const auto bundled_request = [](const std::string& name, const std::string& surface_file) {
    paver::PipelineRequest request;
    request.map = std::make_shared<const paver::SurfaceMap>(paver::build_surface_map(
        paver::load_surface(fs::path(PAVER_SOURCE_DIR) / "assets/surfaces" / surface_file).mesh));
    request.design = paver::load_design(fs::path(PAVER_SOURCE_DIR) / "assets/designs" / (name + ".json"));
    return request;
  };

  if (designs) {
    std::printf("\nWhole pavement per bundled design, ms (map built once, not counted)\n");
    print_header("design");
    out["designs"] = nlohmann::json::array();
    for (const auto& [name, surface_file] : design_surfaces())
      pave_with_each(bundled_request(name, surface_file), name, out["designs"]);
  }
  if (!sweep.empty()) {
    // The torus design (479 particles at D = 7) with D scaled for about n particles each.
    const paver::PipelineRequest torus = bundled_request("torus_tri_d7", design_surfaces().at("torus_tri_d7"));
    const double torus_particles = 479;
    std::printf("\nWhole pavement of torus_tri_d7 against its size, ms\n");
    print_header("about n particles");
    out["sweep"] = nlohmann::json::array();
    for (int n : sweep) {
      paver::PipelineRequest request = torus;
      request.design.pattern.spacing *= std::sqrt(torus_particles / std::max(1, n));
      pave_with_each(request, std::to_string(n), out["sweep"]);
    }
  }
  if (!json_path.empty()) {
    paver::write_text_atomically(json_path, out.dump(2) + "\n");
    std::printf("\nwrote %s\n", json_path.c_str());
  } else {
    std::printf("\n%s\n", out.dump(2).c_str());
  }
  return 0;
}
