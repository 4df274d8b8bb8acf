// paver-render-bench: the views of the renderer the studio and the CLI's PNGs share, on the first
// Vulkan device (lavapipe here): ms per whole image of the 3D and the 2D view at 1280 x 800 for
// 5k to 100k elements, and how many slices the studio's drawing in slices takes for one image.
// The elements are spheres scattered over the bundled pendant (its map), as a run places them.
// Run: build/bin/paver-render-bench --benchmark_format=json
#include "renderer.h"
#include "scene_data.h"

#include "paver/compute/vulkan_context.h"

#include "surface_maps.h"

#include <benchmark/benchmark.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <cstdio>
#include <memory>
#include <random>

namespace {

using namespace paver;

struct Setup {
  std::unique_ptr<render::Renderer> renderer;
  std::shared_ptr<const SurfaceMap> map;
};

Setup& setup() {
  static Setup s = [] {
    Setup out;
    gpu::ContextOptions options;
    options.graphics = true;
    auto context = gpu::VulkanContext::create(options);
    if (!context) return out;
    auto renderer = render::Renderer::create(context.value());
    if (!renderer) return out;
    out.renderer = std::move(renderer.value());
    out.map = test::bundled_map("pendant");
    return out;
  }();
  return s;
}

// `count` spheres at uniformly random points of the surface (by area), each as wide as a tight
// packing of that many would make them.
Elements scattered_spheres(const SurfaceMap& map, int count) {
  const SurfaceMesh& mesh = map.mesh;
  std::vector<double> cumulative;
  double area = 0;
  for (const auto& t : mesh.triangles) {
    area += 0.5 * glm::length(glm::cross(mesh.positions[t.y] - mesh.positions[t.x], mesh.positions[t.z] - mesh.positions[t.x]));
    cumulative.push_back(area);
  }
  const double diameter = std::sqrt(area / count);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0, 1);
  Elements out;
  out.reserve(std::size_t(count));
  for (int i = 0; i < count; ++i) {
    const auto f = std::lower_bound(cumulative.begin(), cumulative.end(), unit(random) * area) - cumulative.begin();
    const glm::ivec3 t = mesh.triangles[std::size_t(f)];
    double a = unit(random), b = unit(random);
    if (a + b > 1) a = 1 - a, b = 1 - b;
    const glm::dvec3 p = mesh.positions[t.x] + a * (mesh.positions[t.y] - mesh.positions[t.x]) +
                         b * (mesh.positions[t.z] - mesh.positions[t.x]);
    const glm::dvec3 n = glm::normalize(glm::cross(mesh.positions[t.y] - mesh.positions[t.x],
                                                   mesh.positions[t.z] - mesh.positions[t.x]));
    out.push_back(ElementKind::Vertex, i, 0, glm::dvec2(0), p, n, diameter, ShapeKind::Sphere);
  }
  return out;
}

render::ViewRequest request(const SurfaceMap& map) {
  return {1280, 800, render::frame_surface(map.mesh), render::frame_map(map), {}};
}

void prepare(benchmark::State& state, Setup& s) {
  const Elements elements = scattered_spheres(*s.map, int(state.range(0)));
  s.renderer->set_surface(*s.map);
  s.renderer->set_elements(elements, render::element_colours(elements, render::ColourMode::ElementType));
}

void BM_WholeImage(benchmark::State& state, int view) {
  Setup& s = setup();
  if (!s.renderer) return state.SkipWithError("no Vulkan device");
  prepare(state, s);
  const render::ViewRequest r = request(*s.map);
  for (auto _ : state) s.renderer->render(view, r);
  state.counters["elements"] = double(state.range(0));
}

void BM_ImageInSlices(benchmark::State& state, int view) {
  Setup& s = setup();
  if (!s.renderer) return state.SkipWithError("no Vulkan device");
  prepare(state, s);
  const render::ViewRequest r = request(*s.map);
  int slices = 0;
  for (auto _ : state) {
    s.renderer->start_drawing(view, r);
    slices = 0;
    while (!s.renderer->draw_more(view, 0.0)) ++slices;
    ++slices;
  }
  state.counters["slices"] = slices;
  state.counters["elements"] = double(state.range(0));
}

BENCHMARK_CAPTURE(BM_WholeImage, view3d, 0)->Arg(2000)->Arg(4000)->Arg(8000)->Arg(20000)->Arg(46000)->Arg(100000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_WholeImage, view2d, 1)->Arg(5000)->Arg(20000)->Arg(46000)->Arg(100000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_ImageInSlices, view3d, 0)->Arg(46000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_ImageInSlices, view2d, 1)->Arg(46000)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
