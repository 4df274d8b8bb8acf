#include "pattern/contact_packing.h"

#include "core/point_hash.h"
#include "map/surface_particles.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <stdexcept>

namespace paver {
namespace {
// FIRE's published constants; the largest step is the one that measured stable on a jammed head
// (0.4 oscillated there).
constexpr double kDtStart = 0.1, kDtMax = 0.3;
constexpr double kAlphaStart = 0.1, kAlphaShrink = 0.99;
constexpr double kDtGrow = 1.1, kDtShrink = 0.5;
constexpr int kWaitAfterStop = 5;
constexpr int kMarginPasses = 8;
// Pairs are listed within contact x (1 + kSkin) and listed again once some particle has moved
// half the skin: until then no pair left out of the list can have come within contact.
constexpr double kSkin = 0.3;
// Overfull: more overlapping pairs than this per particle after the rounds asked (the ring band's
// 1.2, against a few pairs in a jam the base rate clears); then this many rounds more.
constexpr double kOverfullPairs = 0.25;
constexpr int kExtraRounds = 6;

struct Pair {
  int a, b;
};

std::vector<Pair> pairs_within(const SurfaceParticles& p, double reach) {
  const int n = p.size();
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
  for (int i = 0; i < n; ++i)
    if (p.lifted.triangle[i] >= 0) lo = glm::min(lo, p.lifted.position[i]), hi = glm::max(hi, p.lifted.position[i]);
  PointHash near(p.lifted.position, CellGrid(lo, hi, reach), PointHash::Fill::None);
  for (int i = 0; i < n; ++i)
    if (p.lifted.triangle[i] >= 0) near.insert(i);
  std::vector<Pair> pairs;
  for (int i = 0; i < n; ++i) {
    if (p.lifted.triangle[i] < 0) continue;
    near.for_each_near(p.lifted.position[i], [&](int j) {
      if (j > i && glm::length(p.lifted.position[j] - p.lifted.position[i]) < reach) pairs.push_back({i, j});
    });
  }
  return pairs;
}

// One FIRE descent; returns the pairs still overlapping (beyond kSettledOverlap) and the
// overlap each particle carries.
long fire_descent(const SurfaceMap& map, SurfaceParticles& p, const BoundaryIndex& boundary,
                  const ContactPackingOptions& options, std::vector<double>& overlap, ContactPackingReport& report,
                  const std::atomic<bool>* stop) {
  const int n = p.size();
  const double contact = options.contact;
  const double settled = options.settled > 0 ? options.settled : contact * (1 - kSettledOverlap);
  std::vector<glm::dvec3> velocity(n, glm::dvec3(0)), force(n), listed_at, step(n);
  std::vector<Pair> pairs;
  // Each particle's contact factor (graded stones), taken at a listing once the particle has moved
  // kGradeRefresh contacts since it was last taken (grade_field.h).
  std::vector<double> factor(std::size_t(n), 1.0);
  std::vector<glm::dvec3> factored_at(options.grade ? std::size_t(n) : 0,
                                      glm::dvec3(std::numeric_limits<double>::infinity()));
  double dt = kDtStart, alpha = kAlphaStart;
  int since_stop = 0;
  long overlapping = 0;
  for (int iteration = 0;; ++iteration) {
    double drift = 0;
    for (size_t i = 0; i < listed_at.size(); ++i)
      drift = std::max(drift, glm::length(p.lifted.position[i] - listed_at[i]));
    if (listed_at.empty() || drift > 0.5 * kSkin * contact) {
      pairs = pairs_within(p, contact * (1 + kSkin));
      listed_at = p.lifted.position;
      for (std::size_t i = 0; i < factored_at.size(); ++i) {
        if (p.lifted.triangle[i] < 0 || glm::length(p.lifted.position[i] - factored_at[i]) < kGradeRefresh * contact)
          continue;
        factor[i] = options.grade->contact_factor(options.grade->share(p.lifted.position[i], p.lifted.curvature[i]));
        factored_at[i] = p.lifted.position[i];
      }
    }
    std::fill(force.begin(), force.end(), glm::dvec3(0));
    overlap.assign(n, 0);
    overlapping = 0;
    for (const Pair& pair : pairs) {
      // Two held particles neither move nor count: a held frame's own pairs, nearer than a pushed
      // contact, would keep the descent running to its last iteration.
      if (options.movable && !(*options.movable)[pair.a] && !(*options.movable)[pair.b]) continue;
      const glm::dvec3 d = p.lifted.position[pair.b] - p.lifted.position[pair.a];
      const double length = glm::length(d);
      const double pair_factor = 0.5 * (factor[pair.a] + factor[pair.b]);
      const double reach = contact * pair_factor;
      if (length >= reach || length <= 0) continue;
      if (length < settled * pair_factor) {
        ++overlapping;
        overlap[pair.a] += reach - length, overlap[pair.b] += reach - length;
      }
      const glm::dvec3 f = (reach - length) / length * d;
      force[pair.a] -= f, force[pair.b] += f;
    }
    if (overlapping == 0 || iteration >= options.iterations || (stop && stop->load())) break;
    ++report.iterations;
    if (options.movable)
      for (int i = 0; i < n; ++i)
        if (!(*options.movable)[i]) force[i] = glm::dvec3(0);
    // FIRE: steer the velocity towards the force while the motion goes downhill, stop it dead
    // and take smaller steps when it goes uphill. Both stay in each particle's tangent plane.
    double power = 0, v_norm = 0, f_norm = 0;
    for (int i = 0; i < n; ++i) {
      const glm::dvec3 normal = p.lifted.normal[i];
      force[i] -= glm::dot(force[i], normal) * normal;
      velocity[i] -= glm::dot(velocity[i], normal) * normal;
      power += glm::dot(force[i], velocity[i]);
      v_norm += glm::dot(velocity[i], velocity[i]);
      f_norm += glm::dot(force[i], force[i]);
    }
    v_norm = std::sqrt(v_norm), f_norm = std::sqrt(f_norm);
    if (power > 0) {
      const double mix = f_norm > 0 ? alpha * v_norm / f_norm : 0;
      for (int i = 0; i < n; ++i) velocity[i] = (1 - alpha) * velocity[i] + mix * force[i];
      if (++since_stop > kWaitAfterStop) dt = std::min(dt * kDtGrow, kDtMax), alpha *= kAlphaShrink;
    } else {
      std::fill(velocity.begin(), velocity.end(), glm::dvec3(0));
      dt *= kDtShrink, alpha = kAlphaStart, since_stop = 0;
    }
    for (int i = 0; i < n; ++i) {
      velocity[i] += dt * force[i];
      step[i] = dt * velocity[i];
    }
    p.step(map, step);
    p.keep_from_boundary(map, boundary, options.margin);
  }
  return overlapping;
}

// Removes up to `budget` of the most overlapped particles, no two from the same overlap.
int remove_jammed(SurfaceParticles& p, const std::vector<double>& overlap, double contact, int budget) {
  const int n = p.size();
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return overlap[a] > overlap[b]; });
  std::vector<char> removed(n, 0);
  std::vector<int> taken;
  for (int i : order) {
    if (int(taken.size()) >= budget || overlap[i] <= 0) break;
    // Not next to one removed this round: its neighbour's removal may already have made room.
    const bool beside = std::any_of(taken.begin(), taken.end(), [&](int j) {
      return glm::length(p.lifted.position[i] - p.lifted.position[j]) < 2 * contact;
    });
    if (beside) continue;
    removed[i] = 1;
    taken.push_back(i);
  }
  std::vector<glm::dvec2> uv;
  for (int i = 0; i < n; ++i)
    if (!removed[i]) uv.push_back(p.uv[i]);
  p.uv.swap(uv);
  return int(taken.size());
}

}  // namespace

ContactPackingReport pack_by_contact(const SurfaceMap& map, std::vector<glm::dvec2>& uv,
                                     const ContactPackingOptions& options, const std::atomic<bool>* stop) {
  ContactPackingReport report;
  if (options.movable && (options.movable->size() != uv.size() || options.rounds > 1))
    throw std::invalid_argument("pack_by_contact: a movable mask needs one flag per particle and one round");
  if (uv.empty() || !(options.contact > 0)) return report;
  SurfaceParticles p;
  p.uv = uv;
  p.lifted.resize(uv.size());
  lift_points(map, p.uv, p.lifted);
  std::optional<BoundaryIndex> own;
  if (!options.boundary) own.emplace(map.mesh, std::max(options.margin, 1e-9 * options.contact) * 2);
  const BoundaryIndex& boundary = options.boundary ? *options.boundary : *own;
  std::vector<double> overlap;
  // A patch holding more particles than fit stays jammed through every round at the base rate (a
  // narrow ring band whose width the spacing does not divide kept a fifth too many): one still
  // overfull after the rounds asked gets up to kExtraRounds more, each removing twice as many.
  double escalation = 1;
  const int rounds = std::max(1, options.rounds);
  const int most_rounds = rounds > 1 ? rounds + kExtraRounds : 1;
  for (int round = 0;; ++round) {
    report.overlapping_pairs = fire_descent(map, p, boundary, options, overlap, report, stop);
    for (int pass = 0; options.exact_margin && pass < kMarginPasses; ++pass) {
      bool kept = true;
      for (int i = 0; i < p.size() && kept; ++i)
        kept = p.lifted.triangle[i] < 0 || boundary.nearest(p.lifted.position[i]).distance >= options.margin;
      if (kept) break;
      p.keep_from_boundary(map, boundary, options.margin);
    }
    const bool overfull = double(report.overlapping_pairs) > kOverfullPairs * p.size();
    if (report.overlapping_pairs == 0 || (stop && stop->load())) break;
    if (round + 1 >= most_rounds || (round + 1 >= rounds && !overfull)) break;
    if (round + 1 >= rounds) escalation *= 2;
    const int budget = std::max(1, int(escalation * options.remove_share * p.size()));
    report.removed += remove_jammed(p, overlap, options.contact, budget);
    p.lifted.resize(p.uv.size());
    lift_points(map, p.uv, p.lifted);
  }
  uv = p.uv;
  return report;
}

}  // namespace paver
