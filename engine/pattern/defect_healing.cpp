#include "pattern/defect_healing.h"

#include "core/stopwatch.h"
#include "core/point_hash.h"
#include "map/boundary_index.h"
#include "map/lifting.h"
#include "map/surface_particles.h"
#include "pattern/contact_packing.h"
#include "pattern/surface_triangulation.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <random>
#include <utility>

namespace paver {
namespace {

// All in D. A try moves the particles within kPatch of a defect (it and its ring of neighbours),
// never further than kMostMove, so they end within kPatch + kMostMove of it and meet none of the
// particles beyond kHeld, which are not in the try. A mover changes the valences of its
// triangulation neighbours, at most a triangle's longest edge away: those within kCounted are
// counted, from a triangulation that reaches kHull further, so that near the counted ones it is
// the whole pattern's. (A flip between two particles that a mover's triangles touch may reach a
// little further: the count is local, and each pass's recount of the whole pattern is reported.)
constexpr double kPatch = 1.3;
constexpr double kShake = 0.15;  // the random push's standard deviation per axis: the best of 0.1-0.3
constexpr double kMostMove = 0.8;
constexpr double kHeld = kPatch + kMostMove + 1.5;
constexpr double kLongestTriangleEdge = 2.5;  // as the relaxation's triangulation, at its largest spacing
constexpr double kCounted = kPatch + kMostMove + kLongestTriangleEdge;
constexpr double kHull = 1.5;
constexpr double kTriangulated = kCounted + kHull;
constexpr double kRehashAfter = 1.0;  // a particle moved this far since the hash was built: build it again
constexpr int kPackIterations = 300;

// The same draws everywhere: mt19937's output is specified (its distributions are not), each draw
// is its own statement (argument order is not), and the normal is Irwin-Hall's sum of twelve
// uniforms, in + and - alone (log and cos differ between maths libraries).
struct Random {
  std::mt19937 engine{20261129u};
  double uniform() { return (double(engine()) + 0.5) / 4294967296.0; }
  double normal() {
    double sum = -6;
    for (int k = 0; k < 12; ++k) sum += uniform();
    return sum;
  }
  int below(int n) { return int(engine() % std::uint32_t(n)); }
  glm::dvec3 normal3() {
    const double x = normal();
    const double y = normal();
    const double z = normal();
    return {x, y, z};
  }
};

std::vector<int> valences(const std::vector<glm::dvec2>& uv, const std::vector<glm::dvec3>& position, double longest) {
  std::vector<std::pair<int, int>> edges;
  for (const glm::ivec3& t : triangulate_surface_points(uv, position, longest))
    for (int k = 0; k < 3; ++k) edges.push_back(std::minmax(t[k], t[(k + 1) % 3]));
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  std::vector<int> valence(uv.size(), 0);
  for (const auto& [a, b] : edges) ++valence[a], ++valence[b];
  return valence;
}

enum class Outcome { Kept, Moved, Healed };  // the patch as it was; rearranged; with fewer defects

class Healer {
public:
  // Reaches scale with the larger of the spacing and the contact: a gap can make contact the larger.
  Healer(const SurfaceMap& map, const std::vector<glm::dvec2>& uv, const DefectHealingOptions& options)
      : map_(map), options_(options), d_(std::max(options.spacing, options.contact)),
        boundary_(map.mesh, std::max(options.margin, 1e-9 * options.spacing) * 2),
        depth_index_(map.mesh, std::max(options.interior_depth, 1e-9 * options.spacing) * 1.5) {
    p_.uv = uv;
    p_.lifted.resize(uv.size());
    lift_points(map, p_.uv, p_.lifted);
    rehash();
  }

  const std::vector<glm::dvec2>& uv() const { return p_.uv; }

  // The interior particles (on the map) that are not 6-valent, by the whole pattern's triangulation.
  // Also marks which particles are interior, for the tries until the next call.
  std::vector<int> defects() {
    const std::vector<int> valence = valences(p_.uv, p_.lifted.position, kLongestTriangleEdge * d_);
    interior_.resize(p_.size());
    for (int i = 0; i < p_.size(); ++i) interior_[i] = p_.lifted.triangle[i] >= 0 && is_interior(p_.lifted.position[i]);
    std::vector<int> out;
    for (int i = 0; i < p_.size(); ++i)
      if (interior_[i] && valence[i] != 6) out.push_back(i);
    return out;
  }

  // Shakes and packs again the patch around particle `centre`. Keeps the new arrangement when the
  // defects around it are no more than before: fewer heals, as many lets a dislocation wander
  // until it meets one that it cancels (accepting only fewer stopped at a third of the healing).
  Outcome try_around(int centre, Random& random) {
    const glm::dvec3 middle = p_.lifted.position[centre];
    std::vector<int> near;  // within kTriangulated, in index order
    hash_->for_each_near(middle, [&](int j) {
      if (p_.lifted.triangle[j] >= 0 && glm::length(p_.lifted.position[j] - middle) < kTriangulated * d_) near.push_back(j);
    });
    std::sort(near.begin(), near.end());
    std::vector<glm::dvec2> uv(near.size());
    std::vector<glm::dvec3> position(near.size());
    std::vector<char> counted(near.size(), 0), movable;
    std::vector<int> held;  // indices into near
    for (size_t k = 0; k < near.size(); ++k) {
      uv[k] = p_.uv[near[k]];
      position[k] = p_.lifted.position[near[k]];
      const double from_middle = glm::length(position[k] - middle);
      counted[k] = from_middle < kCounted * d_ && interior_[near[k]];
      if (from_middle < kHeld * d_) {
        held.push_back(int(k));
        movable.push_back(from_middle < kPatch * d_);
      }
    }
    const int before = defects_among(uv, position, counted);
    if (before == 0) return Outcome::Kept;  // healed by an earlier try nearby

    SurfaceParticles patch;  // the held particles as lifted already: no second point location
    patch.lifted.resize(held.size());
    for (size_t h = 0; h < held.size(); ++h) {
      const int i = near[held[h]];
      patch.uv.push_back(p_.uv[i]);
      patch.lifted.triangle[h] = p_.lifted.triangle[i];
      patch.lifted.position[h] = p_.lifted.position[i];
      patch.lifted.normal[h] = p_.lifted.normal[i];
      patch.lifted.curvature[h] = p_.lifted.curvature[i];
    }
    std::vector<glm::dvec3> push(patch.uv.size(), glm::dvec3(0));
    for (size_t h = 0; h < held.size(); ++h)
      if (movable[h]) push[h] = kShake * d_ * random.normal3();
    patch.step(map_, std::move(push));
    // Movers that start the interior depth from the boundary (as they are now: interior_ follows
    // every kept move) end within kMostMove of it: they keep the margin without being pushed from
    // it (whose search is most of a try's time otherwise).
    bool all_deep = true;
    for (size_t h = 0; h < held.size(); ++h)
      if (movable[h] && !interior_[near[held[h]]]) all_deep = false;
    const double margin = all_deep && options_.interior_depth - kMostMove * d_ >= options_.margin ? 0 : options_.margin;
    ContactPackingOptions packing;
    packing.contact = options_.contact;
    packing.grade = options_.grade;
    packing.margin = margin;
    packing.iterations = kPackIterations;
    packing.movable = &movable;
    packing.boundary = &boundary_;
    patch.keep_from_boundary(map_, boundary_, margin);
    if (pack_by_contact(map_, patch.uv, packing).overlapping_pairs > 0) return Outcome::Kept;
    // The boundary push moves any particle under the margin, a held one too: such a try is not
    // the arrangement that would be kept.
    for (size_t h = 0; h < held.size(); ++h)
      if (!movable[h] && patch.uv[h] != uv[held[h]]) return Outcome::Kept;
    patch.lift_dropping_outside(map_);
    if (patch.size() != int(held.size())) return Outcome::Kept;
    for (size_t h = 0; h < held.size(); ++h) {
      if (glm::length(patch.lifted.position[h] - position[held[h]]) > kMostMove * d_) return Outcome::Kept;
      uv[held[h]] = patch.uv[h];
      position[held[h]] = patch.lifted.position[h];
    }
    const int after = defects_among(uv, position, counted);
    if (after > before) return Outcome::Kept;
    for (size_t h = 0; h < held.size(); ++h) {
      if (!movable[h]) continue;
      const int i = near[held[h]];
      p_.uv[i] = patch.uv[h];
      p_.lifted.triangle[i] = patch.lifted.triangle[h];
      p_.lifted.position[i] = patch.lifted.position[h];
      p_.lifted.normal[i] = patch.lifted.normal[h];
      p_.lifted.curvature[i] = patch.lifted.curvature[h];
      if (glm::length(p_.lifted.position[i] - hashed_at_[i]) > kRehashAfter * d_) stale_ = true;
      interior_[i] = is_interior(p_.lifted.position[i]);  // a later try may move it again from here
    }
    if (stale_) rehash();
    return after < before ? Outcome::Healed : Outcome::Moved;
  }

private:
  bool is_interior(const glm::dvec3& x) const { return depth_index_.nearest(x).distance >= options_.interior_depth; }

  int defects_among(const std::vector<glm::dvec2>& uv, const std::vector<glm::dvec3>& position,
                    const std::vector<char>& counted) const {
    const std::vector<int> valence = valences(uv, position, kLongestTriangleEdge * d_);
    int defects = 0;
    for (size_t k = 0; k < uv.size(); ++k) defects += counted[k] && valence[k] != 6;
    return defects;
  }

  // Cells wide enough that a particle within kTriangulated of a point is found from where it was
  // hashed, while it has moved less than kRehashAfter since.
  void rehash() {
    hashed_at_ = p_.lifted.position;
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (int i = 0; i < p_.size(); ++i)
      if (p_.lifted.triangle[i] >= 0) lo = glm::min(lo, hashed_at_[i]), hi = glm::max(hi, hashed_at_[i]);
    hash_.emplace(hashed_at_, CellGrid(lo, hi, (kTriangulated + kRehashAfter) * d_), PointHash::Fill::None);
    for (int i = 0; i < p_.size(); ++i)
      if (p_.lifted.triangle[i] >= 0) hash_->insert(i);
    stale_ = false;
  }

  const SurfaceMap& map_;
  const DefectHealingOptions& options_;
  const double d_;
  const BoundaryIndex boundary_;     // reaches the margin: the packing's
  const BoundaryIndex depth_index_;  // reaches the interior depth
  std::vector<char> interior_;
  SurfaceParticles p_;
  std::vector<glm::dvec3> hashed_at_;
  std::optional<PointHash> hash_;
  bool stale_ = false;
};

}  // namespace

DefectHealingReport heal_defects(const SurfaceMap& map, std::vector<glm::dvec2>& uv,
                                 const DefectHealingOptions& options, const std::atomic<bool>* stop) {
  const Stopwatch watch;
  DefectHealingReport report;
  if (uv.size() < 7 || !(options.spacing > 0) || !(options.contact > 0) || (stop && stop->load())) return report;
  Healer healer(map, uv, options);
  Random random;
  std::vector<int> defects = healer.defects();
  report.defects_before = int(defects.size());
  for (int sweep = 0; sweep < options.sweeps && !defects.empty() && !(stop && stop->load()); ++sweep) {
    // A fresh order each pass (Fisher-Yates on the specified engine), so no corner always goes first.
    for (int k = int(defects.size()) - 1; k > 0; --k) std::swap(defects[k], defects[random.below(k + 1)]);
    for (int centre : defects) {
      if (stop && stop->load()) break;
      ++report.tries;
      report.moved += healer.try_around(centre, random) != Outcome::Kept;
    }
    defects = healer.defects();
  }
  report.defects_after = int(defects.size());
  uv = healer.uv();
  report.milliseconds = watch.milliseconds();
  return report;
}

}  // namespace paver
