#include "pattern/particle_relaxation.h"

#include "core/stopwatch.h"
#include "core/point_hash.h"
#include "map/boundary_index.h"
#include "map/lifting.h"
#include "map/surface_particles.h"
#include "pattern/contact_packing.h"
#include "pattern/defect_healing.h"
#include "pattern/interior_depth.h"
#include "pattern/surface_triangulation.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace paver {
namespace {

constexpr int kIterations = 800;
constexpr int kPopulationIterations = 400;  // population control only before this
constexpr int kRetriangulateEvery = 5;
constexpr double kPressure = 1.1;  // bars push until 1.1x their length (DistMesh: 1.2; 1.1 left fewer defects here)
constexpr double kStep = 0.2;               // DistMesh's time step
constexpr double kMaxMove = 0.2;            // of the local spacing per iteration
constexpr double kSettled = 2e-4;           // of the local spacing: the largest move when settled
constexpr double kThin = 0.7;               // seeds nearer each other than this x spacing thin out
constexpr double kCollapseBelow = 0.55;     // a bar this short (x spacing) is a pile-up: merge
constexpr double kSplitAbove = 1.7;         // a bar this long (x spacing) spans a hole: split
constexpr double kLongestEdge = 2.5;        // triangles with a longer 3D edge (x spacing) are dropped
constexpr double kPopulationShare = 0.03;   // population control changes at most 3% per step
constexpr double kLoose = 1.06;  // the count aims the mean bar 6% past the spacing: room for contact
constexpr double kCountTolerance = 0.005;   // the count is left alone within 0.5% of the wanted one
constexpr int kLocalPopulationIterations = 150;  // pile-ups and holes are fixed before this
// A packing that removed more than this share of the particles is followed by a second relaxation
// without population control, and packed again.
constexpr double kRelaxAgainAfterJammed = 0.05;
// The count above leaves the particles just short of jamming at contact; the packing rounds
// remove the few that still find no room (measured on the bunny head: docs/topology.md).
constexpr int kPackingIterations = 400;
constexpr int kPackingRounds = 12;

struct Bar {
  int a, b;
};

struct Particles : SurfaceParticles {
  std::vector<double> spacing;
  // Graded stones: each particle's grade factor and where it was taken, again once the particle
  // has moved kGradeRefresh spacings (grade_field.h).
  std::vector<double> grade_factor;
  std::vector<glm::dvec3> graded_at;

  double bar_length(Bar b) const { return glm::length(lifted.position[b.a] - lifted.position[b.b]); }
  double bar_spacing(Bar b) const { return 0.5 * (spacing[b.a] + spacing[b.b]); }

  // Lifts, drops what fell outside the map (a seed or a split midpoint over a concave boundary)
  // and updates each particle's wanted spacing.
  void lift(const SurfaceMap& map, const RelaxationTarget& target) {
    lift_dropping_outside(map);
    graded_at.clear();  // the particles are renumbered
    update_spacing(map, target);
  }
  void update_spacing(const SurfaceMap& map, const RelaxationTarget& target) {
    spacing.resize(uv.size());
    const GradeField* grade = target.grade;
    if (grade && graded_at.size() != uv.size()) {
      graded_at.assign(uv.size(), glm::dvec3(std::numeric_limits<double>::infinity()));
      grade_factor.assign(uv.size(), 1.0);
    }
    for (int i = 0; i < size(); ++i) {
      spacing[i] = relaxation_spacing(map, target, lifted.curvature[i]);
      if (!grade) continue;
      if (!(glm::length(lifted.position[i] - graded_at[i]) < kGradeRefresh * target.spacing)) {
        grade_factor[i] = grade->spacing_factor(grade->share(lifted.position[i], lifted.curvature[i]));
        graded_at[i] = lifted.position[i];
      }
      spacing[i] *= grade_factor[i];
    }
  }
};

std::vector<Bar> bars_of(const std::vector<glm::ivec3>& triangles) {
  std::vector<Bar> bars;
  bars.reserve(triangles.size() * 3);
  for (const glm::ivec3& t : triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      bars.push_back({std::min(a, b), std::max(a, b)});
    }
  std::sort(bars.begin(), bars.end(), [](Bar x, Bar y) { return x.a != y.a ? x.a < y.a : x.b < y.b; });
  bars.erase(std::unique(bars.begin(), bars.end(), [](Bar x, Bar y) { return x.a == y.a && x.b == y.b; }),
             bars.end());
  return bars;
}

// The bars' root-mean-square length over their wanted spacing (DistMesh's scale); 1 without bars.
double mean_bar_scale(const Particles& p, const std::vector<Bar>& bars) {
  double sum_l2 = 0, sum_h2 = 0;
  for (const Bar& b : bars) {
    const double l = p.bar_length(b), h = p.bar_spacing(b);
    sum_l2 += l * l, sum_h2 += h * h;
  }
  return sum_h2 > 0 ? std::sqrt(sum_l2 / sum_h2) : 1;
}

// Keeps seeds greedily, in their order, when no kept seed lies nearer than kThin x spacing.
void thin_seeds(Particles& p, double largest_spacing) {
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (const glm::dvec3& x : p.lifted.position) lo = glm::min(lo, x), hi = glm::max(hi, x);
  PointHash kept_near(p.lifted.position, CellGrid(lo, hi, kThin * largest_spacing), PointHash::Fill::None);
  std::vector<int> kept;
  for (int i = 0; i < p.size(); ++i) {
    bool clear = true;
    kept_near.for_each_near(p.lifted.position[i], [&](int j) {
      if (glm::length(p.lifted.position[i] - p.lifted.position[j]) < kThin * 0.5 * (p.spacing[i] + p.spacing[j]))
        clear = false;
    });
    if (!clear) continue;
    kept_near.insert(i);
    kept.push_back(i);
  }
  std::vector<glm::dvec2> uv;
  for (int i : kept) uv.push_back(p.uv[i]);
  p.uv.swap(uv);
}

// Collapses pile-ups and splits holes; then, by count, the shortest or longest bars until the
// mean bar matches the spacing. Each particle takes part in one change per step.
void control_population(Particles& p, const std::vector<Bar>& bars, bool allow_local, RelaxationReport& report) {
  const int n = p.size();
  if (bars.empty()) return;
  std::vector<double> ratio(bars.size());
  for (size_t e = 0; e < bars.size(); ++e) ratio[e] = p.bar_length(bars[e]) / p.bar_spacing(bars[e]);
  // Density goes with 1 / spacing^2: the count that would make the mean bar kLoose x the spacing.
  const double scale = mean_bar_scale(p, bars) / kLoose;
  const double wanted = n * scale * scale;
  const int budget = std::max(1, int(kPopulationShare * n));
  // Half the difference per step, and none within a tolerance, so the count settles instead of
  // churning (every change leaves a defect to heal).
  int change = std::abs(wanted - n) > kCountTolerance * n + 1 ? int(std::lround(0.5 * (wanted - n))) : 0;
  change = std::clamp(change, -budget, budget);

  std::vector<int> order(bars.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int x, int y) { return ratio[x] < ratio[y]; });
  std::vector<char> touched(n, 0), removed(n, 0);
  std::vector<glm::dvec2> added;
  const auto collapse = [&](int e) {
    const Bar b = bars[e];
    if (touched[b.a] || touched[b.b]) return false;
    touched[b.a] = touched[b.b] = 1;
    p.uv[b.a] = 0.5 * (p.uv[b.a] + p.uv[b.b]);
    removed[b.b] = 1;
    ++report.removed;
    return true;
  };
  const auto split = [&](int e) {
    const Bar b = bars[e];
    if (touched[b.a] || touched[b.b]) return false;
    touched[b.a] = touched[b.b] = 1;
    added.push_back(0.5 * (p.uv[b.a] + p.uv[b.b]));
    ++report.inserted;
    return true;
  };
  // Shortest bars first: pile-ups, then as many more as the count asks to lose.
  const int to_remove = std::max(0, -change), to_add = std::max(0, change);
  int done = 0;
  for (size_t k = 0; k < order.size(); ++k) {
    const bool pile_up = allow_local && ratio[order[k]] < kCollapseBelow;
    if (!pile_up && done >= to_remove) break;
    done += collapse(order[k]);
  }
  // Longest bars first: holes, then as many more as the count asks to gain.
  done = 0;
  for (size_t k = order.size(); k-- > 0;) {
    const bool hole = allow_local && ratio[order[k]] > kSplitAbove;
    if (!hole && done >= to_add) break;
    done += split(order[k]);
  }

  std::vector<glm::dvec2> uv;
  uv.reserve(n + added.size());
  for (int i = 0; i < n; ++i)
    if (!removed[i]) uv.push_back(p.uv[i]);
  uv.insert(uv.end(), added.begin(), added.end());
  p.uv.swap(uv);
}

}  // namespace

double relaxation_spacing(const SurfaceMap& map, const RelaxationTarget& target, double kappa) {
  return target.spacing * (1 + target.c + target.m * normalised_curvature(map, kappa));
}

namespace {

// DistMesh iterations from `first` (kIterations at most), with population control before
// kPopulationIterations; ends early once settled past them.
void relax_bars(const SurfaceMap& map, const RelaxationTarget& target, const BoundaryIndex& boundary, double largest,
                int first, Particles& p, RelaxationReport& report, const std::atomic<bool>* stop) {
  std::vector<glm::ivec3> triangles;
  std::vector<Bar> bars;
  std::vector<glm::dvec3> force;
  std::vector<glm::dvec3> moved_from;
  for (int iteration = first; iteration < kIterations; ++iteration) {
    if (stop && stop->load()) break;
    report.iterations = iteration + 1;
    if ((iteration - first) % kRetriangulateEvery == 0) {
      triangles = triangulate_surface_points(p.uv, p.lifted.position, kLongestEdge * largest);
      bars = bars_of(triangles);
      if (iteration > 0 && iteration < kPopulationIterations) {
        control_population(p, bars, iteration < kLocalPopulationIterations, report);
        p.lift(map, target);
        triangles = triangulate_surface_points(p.uv, p.lifted.position, kLongestEdge * largest);
        bars = bars_of(triangles);
      }
    }
    const int n = p.size();
    if (n < 3) break;
    // DistMesh's scale: bars push until they are kPressure times the spacing, scaled by the
    // present mean, so the pressure spreads the particles evenly whatever their number.
    const double scale = mean_bar_scale(p, bars);
    force.assign(n, glm::dvec3(0));
    for (const Bar& b : bars) {
      const glm::dvec3 d = p.lifted.position[b.a] - p.lifted.position[b.b];
      const double l = glm::length(d);
      const double rest = kPressure * scale * p.bar_spacing(b);
      if (l <= 0 || l >= rest) continue;
      const glm::dvec3 f = (rest - l) / l * d;
      force[b.a] += f, force[b.b] -= f;
    }
    // Steps in each particle's tangent plane, capped; then the boundary margin.
    moved_from = p.lifted.position;
    std::vector<glm::dvec3> step(n);
    for (int i = 0; i < n; ++i) {
      step[i] = kStep * force[i];
      const double cap = kMaxMove * p.spacing[i];
      if (glm::length(step[i]) > cap) step[i] *= cap / glm::length(step[i]);
    }
    p.step(map, std::move(step));
    p.keep_from_boundary(map, boundary, target.boundary_margin);
    double largest_move = 0;
    for (int i = 0; i < n; ++i) {
      largest_move = std::max(largest_move, glm::length(p.lifted.position[i] - moved_from[i]) / p.spacing[i]);
    }
    p.update_spacing(map, target);
    if (iteration >= kPopulationIterations && largest_move < kSettled) break;
  }
}

}  // namespace

RelaxedParticles relax_particles(const SurfaceMap& map, const std::vector<glm::dvec2>& seeds,
                                 const RelaxationTarget& target, const std::atomic<bool>* stop) {
  const Stopwatch watch;
  RelaxedParticles out;
  RelaxationReport& report = out.report;
  const double largest = target.spacing * (1 + target.c + std::max(target.m, 0.0));
  Particles p;
  p.uv = seeds;
  p.lift(map, target);
  thin_seeds(p, largest);
  p.lift(map, target);
  report.seeds_kept = p.size();

  const BoundaryIndex boundary(map.mesh, std::max(target.boundary_margin, 1e-9 * largest) * 2);
  relax_bars(map, target, boundary, largest, 0, p, report, stop);
  if (target.contact > 0 && !(stop && stop->load())) {
    ContactPackingOptions packing;
    packing.contact = target.contact;
    packing.grade = target.grade;
    packing.margin = target.boundary_margin;
    packing.iterations = kPackingIterations;
    packing.rounds = kPackingRounds;
    ContactPackingReport packed = pack_by_contact(map, p.uv, packing, stop);
    report.packing_iterations = packed.iterations;
    report.jammed = packed.removed;
    if (packed.removed > kRelaxAgainAfterJammed * p.size() && !(stop && stop->load())) {
      // So many removed (a narrow band whose width the spacing does not divide) leave holes that
      // packing, which only pushes apart, cannot close: the bars spread the rest evenly again.
      p.lift(map, target);
      relax_bars(map, target, boundary, largest, kPopulationIterations, p, report, stop);
      packed = pack_by_contact(map, p.uv, packing, stop);
      report.packing_iterations += packed.iterations;
      report.jammed += packed.removed;
    }
    // Packing freezes dislocations in; healing cancels some (docs/topology.md).
    DefectHealingOptions healing;
    healing.spacing = largest;
    healing.contact = target.contact;
    healing.grade = target.grade;
    healing.margin = target.boundary_margin;
    healing.interior_depth = kInteriorDepth * target.spacing;
    report.healing = heal_defects(map, p.uv, healing, stop);
    p.lift(map, target);
  }
  out.triangles = triangulate_surface_points(p.uv, p.lifted.position, kLongestEdge * largest);
  if (target.grade) {
    // Graded stones lie closer where they are smaller: a triangle that the largest spacing lets
    // through can span two or three small rim stones (a chord across a ring's inner rim). Such a
    // bar is a hole's, as population control judges one.
    std::erase_if(out.triangles, [&](const glm::ivec3& t) {
      for (int k = 0; k < 3; ++k) {
        const Bar bar{t[k], t[(k + 1) % 3]};
        if (p.bar_length(bar) > kSplitAbove * p.bar_spacing(bar)) return true;
      }
      return false;
    });
  }
  out.uv = std::move(p.uv);
  report.milliseconds = watch.milliseconds();
  return out;
}

}  // namespace paver
