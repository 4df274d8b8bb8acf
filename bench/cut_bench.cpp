// The subtractive solid's cost: seats cut into a flat plate, 100 and 1,000 of them (issue 14
// asks for the time of 1,000 cutters). Run: build/bin/paver-cut-bench --benchmark_format=json
#include "cut/solid_cut.h"

#include <benchmark/benchmark.h>

#include <cmath>

namespace paver {
namespace {

// A plate `cells` x `cells` of unit squares at z = 0 with `stones` seats of 1 mm on a 1.2 mm grid.
void cut_seats(benchmark::State& state) {
  const int stones = static_cast<int>(state.range(0));
  const int per_row = static_cast<int>(std::ceil(std::sqrt(double(stones))));
  const double size = 1.2 * per_row + 1.2;
  const int cells = 2 * per_row;
  SurfaceMap plate;
  for (int j = 0; j <= cells; ++j)
    for (int i = 0; i <= cells; ++i) plate.mesh.positions.emplace_back(size * i / cells, size * j / cells, 0.0);
  const auto at = [&](int i, int j) { return j * (cells + 1) + i; };
  for (int j = 0; j < cells; ++j)
    for (int i = 0; i < cells; ++i) {
      plate.mesh.triangles.emplace_back(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      plate.mesh.triangles.emplace_back(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  plate.normals.assign(plate.mesh.positions.size(), glm::dvec3(0, 0, 1));
  Elements elements;
  for (int k = 0; k < stones; ++k) {
    const glm::dvec2 c(1.2 * (k % per_row) + 1.3, 1.2 * (k / per_row) + 1.3);
    elements.push_back(ElementKind::Vertex, k, 0, c, {c.x, c.y, 0.0}, {0, 0, 1}, 1.0, ShapeKind::Gem);
  }
  CutSolid cut;
  for (auto _ : state) {
    cut = cut_pavement(plate, elements, {.cutter = CutterKind::Seat, .thickness = 1.0});
    benchmark::DoNotOptimize(cut.volume);
  }
  state.counters["cutters"] = cut.cutters;
  state.counters["triangles"] = double(cut.mesh.triangles.size());
  state.counters["ms_per_cutter"] = cut.milliseconds / std::max(1, cut.cutters);
}
BENCHMARK(cut_seats)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
}  // namespace paver

BENCHMARK_MAIN();
