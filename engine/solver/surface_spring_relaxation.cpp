#include "solver/surface_spring_relaxation.h"

#include "core/stopwatch.h"
#include "core/point_hash.h"
#include "core/contact_rule.h"
#include "map/boundary_index.h"
#include "map/surface_particles.h"
#include "pattern/bar_length_floor.h"
#include "pattern/adaptive_pattern.h"
#include "pattern/contact_packing.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cstdint>
#include <limits>

namespace paver {
namespace {
constexpr double kSpringWeight = 0.5;  // honeycomb springs: half the length error per iteration

// The honeycomb's springs pull each edge to its eq. 5 target while contact pushes every pair
// apart (a projection, averaged over a particle's pairs); particles keep `margin` from the boundary.
void relax_honeycomb_springs(const SurfaceMap& map, const Pattern& pattern, std::vector<glm::dvec2>& points,
                             const Design& design, const SurfaceSpringOptions& options, double contact,
                             const BoundaryIndex& boundary, double margin, const std::atomic<bool>* stop,
                             SolveReport& report) {
  const int n = int(points.size());
  const double spacing = design.pattern.spacing;
  const SolverParams& params = design.solver;
  SurfaceParticles p;
  p.uv = points;
  p.lifted.resize(n);
  // A honeycomb point (a map centroid) over a concave stretch of the boundary lies outside the
  // map: it carries no element and stays where it is.
  lift_points(map, p.uv, p.lifted);
  std::vector<char> outside(n);
  for (int i = 0; i < n; ++i) outside[i] = p.lifted.triangle[i] < 0;

  std::vector<glm::dvec3> force(n), from(n), push(n);
  std::vector<int> pushes(n);
  for (int iteration = 0; iteration < options.iterations; ++iteration) {
    if (stop && stop->load()) {
      report.reason = StopReason::Observer;
      break;
    }
    report.iterations = iteration + 1;
    std::fill(force.begin(), force.end(), glm::dvec3(0));
    for (int e = 0; e < pattern.edge_count(); ++e) {
      const int a = pattern.edge_a[e], b = pattern.edge_b[e];
      if (outside[a] || outside[b]) continue;
      const glm::dvec3 d = p.lifted.position[b] - p.lifted.position[a];
      const double length = glm::length(d);
      if (length <= 0) continue;
      const double kappa = 0.5 * (p.lifted.curvature[a] + p.lifted.curvature[b]);
      const double rest = pattern.edge_rest_length[e] * (1 + params.c + params.m * normalised_curvature(map, kappa)) *
                          (1 + kContactAim);
      const glm::dvec3 f = kSpringWeight * (length - rest) / length * d;
      force[a] += f, force[b] -= f;
    }
    long contacts = 0;
    std::fill(pushes.begin(), pushes.end(), 0);
    std::fill(push.begin(), push.end(), glm::dvec3(0));
    if (contact > 0) {
      glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
      for (int i = 0; i < n; ++i)
        if (!outside[i]) lo = glm::min(lo, p.lifted.position[i]), hi = glm::max(hi, p.lifted.position[i]);
      // Particles off the map are not bucketed: they have no position.
      PointHash near(p.lifted.position, CellGrid(lo, hi, contact), PointHash::Fill::None);
      for (int i = 0; i < n; ++i)
        if (!outside[i]) near.insert(i);
      for (int i = 0; i < n; ++i) {
        if (outside[i]) continue;
        near.for_each_near(p.lifted.position[i], [&](int j) {
          if (j <= i) return;
          const glm::dvec3 d = p.lifted.position[j] - p.lifted.position[i];
          const double length = glm::length(d);
          if (length >= contact || length <= 0) return;
          ++contacts;
          const glm::dvec3 f = 0.5 * (length - contact) / length * d;
          push[i] += f, push[j] -= f;
          ++pushes[i], ++pushes[j];
        });
      }
    }
    from = p.lifted.position;
    std::vector<glm::dvec3> step(n);
    for (int i = 0; i < n; ++i) {
      // Contact as a projection: each overlap corrected in full, averaged over a particle's pairs.
      step[i] = options.step * force[i] + (pushes[i] > 0 ? push[i] / double(pushes[i]) : glm::dvec3(0));
      const double cap = options.max_move * spacing;
      if (glm::length(step[i]) > cap) step[i] *= cap / glm::length(step[i]);
    }
    p.step(map, std::move(step));
    p.keep_from_boundary(map, boundary, margin);
    double largest = 0;
    for (int i = 0; i < n; ++i) largest = std::max(largest, glm::length(p.lifted.position[i] - from[i]));
    report.last_max_step = float(largest);
    if (largest < options.settled * spacing && contacts == 0) {
      report.reason = StopReason::Converged;
      break;
    }
  }
  points = p.uv;
}
}  // namespace

SolveReport relax_pattern_on_surface(const SurfaceMap& map, const Pattern& pattern, std::vector<glm::dvec2>& points,
                                     const Design& design, const SurfaceSpringOptions& options,
                                     const std::atomic<bool>* stop) {
  const Stopwatch watch;
  SolveReport report;
  const int n = int(points.size());
  if (n == 0) return report;
  const double spacing = design.pattern.spacing;
  // Particles keep the contact rule of the elements on and around their bars (bar_length_floor.h).
  const double contact = particle_contact_distance(design);
  const double margin = particle_boundary_margin(map, design, options.grade) * (1 + 2 * kContactAim);
  const BoundaryIndex boundary(map.mesh, std::max(margin, 1e-9 * spacing) * 2);

  // A triangle pattern's particles are its vertex elements, packed to contact as they were
  // relaxed: contact alone holds them (springs would hold a compressed patch compressed). A
  // honeycomb needs its springs first, or it folds into triangles.
  const bool hex = design.pattern.tessellation == Tessellation::Hexagon;
  if (hex) relax_honeycomb_springs(map, pattern, points, design, options, contact, boundary, margin, stop, report);
  if (report.reason != StopReason::Observer) {
    ContactPackingOptions packing;
    packing.contact = contact;
    packing.grade = options.grade;
    packing.margin = margin;
    packing.iterations = options.packing_iterations;
    const ContactPackingReport packed = pack_by_contact(map, points, packing, stop);
    report.iterations += packed.iterations;
    if (packed.overlapping_pairs == 0 && report.reason == StopReason::IterationLimit)
      report.reason = StopReason::Converged;
  }
  report.milliseconds = watch.milliseconds();
  return report;
}

}  // namespace paver
