#include "elements/refill.h"

#include "core/stopwatch.h"
#include "elements/boundary_postprocess.h"
#include "core/point_hash.h"
#include "core/contact_rule.h"
#include "map/boundary_walk.h"
#include "map/lifting.h"
#include "map/uv_from_tangent.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <span>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace paver {
namespace {

constexpr int kDirections = 12;
constexpr int kMaxWaves = 1000;  // a hole is crossed in about its width / D waves

// Whether a new element of `diameter` at `p` keeps the contact rule with every element and lies
// at least `spacing` from each (spacing no more than the hash's cell).
bool clears_all(const PointHash& hash, const Elements& elements, const glm::dvec3& p, double diameter, double gap,
                double spacing) {
  bool clear = true;
  hash.for_each_near(p, [&](int j) {
    const double d = glm::length(p - elements.position[j]);
    // The density rule is the V-elements'; every element keeps the contact rule.
    const bool too_dense = elements.kind[j] == ElementKind::Vertex && d < spacing;
    if (too_dense || elements_collide(d, diameter, elements.diameter[j], gap)) clear = false;
  });
  return clear;
}

// The density rule: no closer to any V-element than a triangle packing with the design's area per
// V-element, times eq. 5's growth at the curvature there.
struct DensityRule {
  double packing = 0, c = 0, m = 0;
  explicit DensityRule(const RefillDensity& density)
      : packing(std::sqrt(density.area_per_vertex_element / (0.5 * std::sqrt(3.0)))), c(density.c), m(density.m) {}
  double spacing(const SurfaceMap& map, double curvature) const {
    return packing * (1 + c + m * normalised_curvature(map, curvature));
  }
  double widest() const { return packing * (1 + c + std::max(m, 0.0)); }
};

// A hash over `elements` whose cells are wide enough for every query of a new element of `diameter`.
CellGrid element_grid(const SurfaceMap& map, const Elements& elements, double diameter, double gap, double widest) {
  double largest = diameter;
  for (double d : elements.diameter) largest = std::max(largest, d);
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (const glm::dvec3& p : map.mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const double reach = std::max(0.5 * (largest + diameter) + gap, widest);
  return CellGrid(lo - glm::dvec3(reach), hi + glm::dvec3(reach), reach);
}

}  // namespace

RefillReport refill_bare_regions(const SurfaceMap& map, Elements& elements, const ElementsDesign& spec, double spacing,
                                 const RefillDensity& rule, const std::atomic<bool>* stop) {
  const Stopwatch watch;
  RefillReport report;
  if (!spec.vertex.enabled || elements.size() == 0 || map.mesh.positions.empty() || !(rule.area_per_vertex_element > 0))
    return report;
  const double diameter = spec.vertex.scale * spacing;
  const double gap = spec.gap;
  const DensityRule density(rule);
  const auto local_spacing = [&](double curvature) { return density.spacing(map, curvature); };
  const CellGrid grid = element_grid(map, elements, diameter, gap, density.widest());
  PointHash hash(elements.position, grid);

  std::vector<int> seeds(elements.size());
  for (int i = 0; i < int(elements.size()); ++i) seeds[i] = i;
  LiftedPoints seed_lift, lifted;
  std::vector<int> near;
  for (; !seeds.empty() && report.waves < kMaxWaves; ++report.waves) {
    if (stop && stop->load()) break;
    std::vector<glm::dvec2> seed_uv;
    for (int s : seeds) seed_uv.push_back(elements.uv[s]);
    seed_lift.resize(seed_uv.size());
    lift_points(map, seed_uv, seed_lift);
    // Candidates around every seed, aimed a little past the required distance.
    std::vector<glm::dvec2> candidates;
    std::vector<double> wanted;
    std::vector<int> from;
    for (size_t k = 0; k < seeds.size(); ++k) {
      const int s = seeds[k];
      const int t = seed_lift.triangle[k];
      if (t < 0) continue;
      const glm::dvec3 n = elements.normal[s];
      const glm::ivec3 tri = map.mesh.triangles[t];
      glm::dvec3 t1 = map.mesh.positions[tri.y] - map.mesh.positions[tri.x];
      t1 = glm::normalize(t1 - glm::dot(t1, n) * n);
      const glm::dvec3 t2 = glm::cross(n, t1);
      const UvFromTangent uv_step(map, t);
      const double need = std::max(contact_distance(elements.diameter[s], diameter, gap),
                                   local_spacing(seed_lift.curvature[k])) *
                          (1 + 2 * kContactAim);
      // Inside a pattern most directions point at a neighbour: they are dropped here, before the
      // lifts and checks that cost per candidate (a 1M-element lattice would offer 12M). The
      // candidate lands near its tangent-plane point (closer than half the step on any surface
      // the pattern can pave), so one with an element within half its contact distance of that
      // point would fail the check below anyway.
      near.clear();
      hash.for_each_near(elements.position[s], [&](int j) {
        if (j != s) near.push_back(j);
      });
      for (int d = 0; d < kDirections; ++d) {
        const double angle = 2 * std::numbers::pi * d / kDirections;
        const glm::dvec3 step = need * (std::cos(angle) * t1 + std::sin(angle) * t2);
        const glm::dvec3 tangent_point = elements.position[s] + step;
        if (std::any_of(near.begin(), near.end(), [&](int q) {
              return glm::length(elements.position[q] - tangent_point) <
                     0.5 * std::min(need, contact_distance(diameter, elements.diameter[q], gap));
            }))
          continue;
        candidates.push_back(elements.uv[s] + uv_step(step));
        wanted.push_back(need);
        from.push_back(s);
      }
    }
    lifted.resize(candidates.size());
    lift_points(map, candidates, lifted);
    // One correction along the same uv direction, so the chord over a curved surface is the
    // distance aimed at.
    for (size_t c = 0; c < candidates.size(); ++c) {
      if (lifted.triangle[c] < 0) continue;
      const double got = glm::length(lifted.position[c] - elements.position[from[c]]);
      if (got > 0) candidates[c] = elements.uv[from[c]] + (candidates[c] - elements.uv[from[c]]) * (wanted[c] / got);
    }
    lift_points(map, candidates, lifted);
    Elements trial;
    for (size_t c = 0; c < candidates.size(); ++c)
      trial.push_back(ElementKind::Vertex, -1, 0, candidates[c],
                      lifted.triangle[c] < 0 ? glm::dvec3(0) : lifted.position[c],
                      lifted.triangle[c] < 0 ? glm::dvec3(0, 0, 1) : lifted.normal[c], diameter, spec.vertex.shape);
    const double margin = boundary_margin(map, spec.margin, spec.gap);
    const std::vector<double> to_boundary = distances_to_boundary(map, trial, margin);
    std::vector<int> next;
    for (size_t c = 0; c < candidates.size(); ++c) {
      if (lifted.triangle[c] < 0 || !keeps_margin(to_boundary[c], diameter, margin)) continue;
      if (!clears_all(hash, elements, lifted.position[c], diameter, gap, local_spacing(lifted.curvature[c]))) continue;
      elements.push_back(ElementKind::Vertex, -1, 0, candidates[c], lifted.position[c], lifted.normal[c], diameter,
                         spec.vertex.shape);
      hash.insert(int(elements.size()) - 1);
      next.push_back(int(elements.size()) - 1);
      ++report.added;
    }
    seeds.swap(next);
  }
  report.milliseconds = watch.milliseconds();
  return report;
}

void refill_seams(const SurfaceMap& map, Elements& elements, const ElementsDesign& spec, double spacing,
                  const RefillDensity& rule, RefillReport& report) {
  if (!is_atlas(map) || !spec.vertex.enabled || spec.allow_overlap || !(rule.area_per_vertex_element > 0)) return;
  const Stopwatch watch;
  const double diameter = spec.vertex.scale * spacing;
  const DensityRule density(rule);
  const CellGrid grid = element_grid(map, elements, diameter, spec.gap, density.widest());
  PointHash hash(elements.position, grid);
  // Along the seam in steps of a tenth of a diameter; across it at these shares of a diameter into
  // the chart walked (the other side is walked with its own chart's loop).
  constexpr std::array<double, 4> kInto = {1e-6, 0.15, 0.3, 0.45};
  LiftedPoints lifted;
  lifted.resize(1);
  const BoundaryWalk seams(map);
  for (int loop = 0; loop < int(map.mesh.boundary_loops.size()); ++loop)
    seams.walk(loop, 0.1 * diameter, [&](const BoundarySample& at) {
      const UvFromTangent uv_step(map, at.triangle);
      for (const double share : kInto) {
        const glm::dvec2 uv = at.uv + uv_step(at.into * (share * diameter));
        if (lift_points(map, std::span(&uv, 1), lifted) > 0) continue;
        // The uv step is linear in the triangle; far from the seam the lift is the truth.
        if (glm::length(lifted.position[0] - at.position) > diameter) continue;
        if (!clears_all(hash, elements, lifted.position[0], diameter, spec.gap,
                        density.spacing(map, lifted.curvature[0])))
          continue;
        elements.push_back(ElementKind::Vertex, -1, 0, uv, lifted.position[0], lifted.normal[0], diameter,
                           spec.vertex.shape);
        hash.insert(int(elements.size()) - 1);
        ++report.added, ++report.on_seams;
        return;
      }
    });
  report.milliseconds += watch.milliseconds();
}

}  // namespace paver
