#include "elements/bare_spots.h"

#include "core/contact_rule.h"
#include "core/point_hash.h"
#include "core/stopwatch.h"
#include "elements/boundary_postprocess.h"
#include "elements/element_proximity.h"
#include "map/boundary_index.h"
#include "map/lifting.h"
#include "pattern/contact_packing.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <optional>
#include <tuple>

namespace paver {

double SpotBasis::spot_stone_at(const SurfaceMap& map, int f, glm::dvec2 w, glm::dvec2 uv) const {
  if (c == 0 && m == 0 && guidance.empty() && !grade) return spot_stone;
  const glm::ivec3 t = map.mesh.triangles[f];
  const double kappa =
      (1 - w.x - w.y) * map.curvature[t.x] + w.x * map.curvature[t.y] + w.y * map.curvature[t.z];
  const double growth = (1 + c + m * normalised_curvature(map, kappa)) * guidance_factor(guidance, uv);
  // The regular hole at the grown spacing: its centre farther from the elements by the growth.
  const double hole = 2 * (growth * hole_reach - 0.5 * stone - gap);
  if (!grade) return std::max(kSpotStoneShare * stone, kSpotOverHole * hole);
  // Where the stones are graded smaller, so is the stone a spot must fit: a hole is judged against
  // the stones around it.
  const std::vector<glm::dvec3>& p = map.mesh.positions;
  const glm::dvec3 at = (1 - w.x - w.y) * p[std::size_t(t.x)] + w.x * p[std::size_t(t.y)] + w.y * p[std::size_t(t.z)];
  return std::max(kSpotStoneShare * stone, kSpotOverHole * hole) * grade->share(at, kappa);
}

double SpotBasis::narrowest_spot_stone() const {
  if (c == 0 && m == 0 && guidance.empty() && !grade) return spot_stone;
  const double least = std::max(0.0, 1 + c + std::min(m, 0.0)) * (guidance.empty() ? 1.0 : kGuidanceMin);
  const double narrowest =
      std::max(kSpotStoneShare * stone, kSpotOverHole * 2 * (least * hole_reach - 0.5 * stone - gap));
  return grade ? narrowest * grade->least_share() : narrowest;
}

FreeRoom::FreeRoom(const SurfaceMap& map, const Elements& elements, const SpotBasis& basis, double reach)
    : elements_(elements), gap_(basis.gap), margin_(basis.margin), reach_(reach),
      rims_(is_atlas(map) ? nullptr : std::make_unique<BoundaryIndex>(map.mesh, reach + basis.margin)),
      hash_(elements.position, grid(map, elements, reach)) {}

FreeRoom::~FreeRoom() = default;

double FreeRoom::to_elements(const glm::dvec3& p) const {
  double room = reach_;
  hash_.for_each_near(p, [&](int j) {
    room = std::min(room, glm::length(p - elements_.position[j]) - 0.5 * elements_.diameter[j] - gap_);
  });
  return room;
}

double FreeRoom::to_rims(const glm::dvec3& p) const { return rims_ ? rims_->nearest(p).distance - margin_ : reach_; }

CellGrid FreeRoom::grid(const SurfaceMap& map, const Elements& elements, double reach) {
  double largest = 0;
  for (double d : elements.diameter) largest = std::max(largest, d);
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (const glm::dvec3& p : map.mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const double cell = reach + 0.5 * largest;
  return CellGrid(lo - glm::dvec3(cell), hi + glm::dvec3(cell), cell);
}

namespace {

// A piece of a mesh triangle: its corners in 3D and as (u, v) in the triangle (p = a + u ab + v ac).
struct Piece {
  glm::dvec3 p[3];
  glm::dvec2 w[3];
};

// Splits the pieces of face f until each is smaller than `step` or holds no spot for certain (the
// widest stone changes by at most twice the distance moved), and keeps every point where a stone
// of `wanted` fits.
void search_face(const SurfaceMap& map, const FreeRoom& room, const SpotBasis& basis, int f, double step,
                 double slack, SpotSearch& out) {
  const double narrowest = basis.narrowest_spot_stone() - slack;
  const glm::ivec3 t = map.mesh.triangles[f];
  std::vector<Piece> stack = {{{map.mesh.positions[t.x], map.mesh.positions[t.y], map.mesh.positions[t.z]},
                               {glm::dvec2(0, 0), glm::dvec2(1, 0), glm::dvec2(0, 1)}}};
  while (!stack.empty()) {
    const Piece piece = stack.back();
    stack.pop_back();
    const glm::dvec3 centre = (piece.p[0] + piece.p[1] + piece.p[2]) / 3.0;
    double radius = 0;
    for (const glm::dvec3& corner : piece.p) radius = std::max(radius, glm::length(corner - centre));
    // The rims are asked only where the elements leave room (they leave none almost everywhere).
    const double to_elements = room.to_elements(centre);
    if (2 * to_elements + 2 * radius < narrowest) continue;
    const double fits = 2 * std::min(to_elements, room.to_rims(centre));
    out.widest = std::max(out.widest, fits);
    if (fits >= narrowest) {
      // The corners in one piece (a band's seamless map wraps), the point wrapped into the period.
      const std::array<glm::dvec2, 3> corner = triangle_uv(map, f);
      const glm::dvec2 w = (piece.w[0] + piece.w[1] + piece.w[2]) / 3.0;
      const glm::dvec2 uv = wrap_point(map, corner[0] + w.x * (corner[1] - corner[0]) + w.y * (corner[2] - corner[0]));
      const double wanted = basis.spot_stone_at(map, f, w, uv) - slack;
      if (fits >= wanted) out.spots.push_back({centre, uv, f, fits, wanted});
    }
    if (fits + 2 * radius < narrowest || radius <= 0.5 * step) continue;
    const glm::dvec3 m01 = 0.5 * (piece.p[0] + piece.p[1]), m12 = 0.5 * (piece.p[1] + piece.p[2]),
                     m20 = 0.5 * (piece.p[2] + piece.p[0]);
    const glm::dvec2 w01 = 0.5 * (piece.w[0] + piece.w[1]), w12 = 0.5 * (piece.w[1] + piece.w[2]),
                     w20 = 0.5 * (piece.w[2] + piece.w[0]);
    stack.push_back({{piece.p[0], m01, m20}, {piece.w[0], w01, w20}});
    stack.push_back({{m01, piece.p[1], m12}, {w01, piece.w[1], w12}});
    stack.push_back({{m20, m12, piece.p[2]}, {w20, w12, piece.w[2]}});
    stack.push_back({{m01, m12, m20}, {w01, w12, w20}});
  }
}

// The spots, the widest first, each a stone of `stone` that keeps the gap to those before it.
std::vector<BareSpot> distinct_spots(std::vector<BareSpot> fitting, double gap, SpotOrder order) {
  std::sort(fitting.begin(), fitting.end(), [order](const BareSpot& a, const BareSpot& b) {
    if (a.fits != b.fits) return order == SpotOrder::WidestFirst ? a.fits > b.fits : a.fits < b.fits;
    return std::tie(a.position.x, a.position.y, a.position.z) < std::tie(b.position.x, b.position.y, b.position.z);
  });
  std::vector<BareSpot> spots;
  if (fitting.empty()) return spots;
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (const BareSpot& s : fitting) lo = glm::min(lo, s.position), hi = glm::max(hi, s.position);
  std::vector<glm::dvec3> taken;
  taken.reserve(fitting.size());
  double widest_wanted = 0;
  for (const BareSpot& s : fitting) widest_wanted = std::max(widest_wanted, s.wanted);
  std::vector<double> wanted;
  PointHash near(taken, CellGrid(lo, hi, widest_wanted + gap), PointHash::Fill::None);
  for (const BareSpot& s : fitting) {
    bool clear = true;
    near.for_each_near(s.position, [&](int k) {
      clear = clear && glm::length(s.position - taken[k]) >= 0.5 * (s.wanted + wanted[k]) + gap;
    });
    if (!clear) continue;
    taken.push_back(s.position);
    wanted.push_back(s.wanted);
    near.insert(int(taken.size()) - 1);
    spots.push_back(s);
  }
  return spots;
}

// Beyond two spot stones and one stone a spot is plainly there: its width is said as "at least".
double reach_of(const SpotBasis& basis) { return 2 * basis.spot_stone + basis.stone; }

}  // namespace

namespace {

// The spots on the faces `faces` (all when empty).
SpotSearch search_faces(const SurfaceMap& map, const Elements& elements, const SpotBasis& basis, double slack,
                        const std::vector<int>& faces, SpotOrder order = SpotOrder::WidestFirst) {
  SpotSearch search;
  if (!(basis.stone > 0) || elements.size() == 0 || map.mesh.face_count() == 0) return search;
  const FreeRoom room(map, elements, basis, reach_of(basis));
  const double step = basis.stone / kSpotSamplesPerStone;
  const int count = faces.empty() ? map.mesh.face_count() : int(faces.size());
  tbb::combinable<SpotSearch> local;
  tbb::parallel_for(tbb::blocked_range<int>(0, count, 16), [&](const tbb::blocked_range<int>& r) {
    SpotSearch& mine = local.local();
    for (int f = r.begin(); f != r.end(); ++f) search_face(map, room, basis, faces.empty() ? f : faces[f], step, slack, mine);
  });
  std::vector<BareSpot> fitting;
  local.combine_each([&](const SpotSearch& s) {
    search.widest = std::max(search.widest, s.widest);
    fitting.insert(fitting.end(), s.spots.begin(), s.spots.end());
  });
  search.widest = std::max(0.0, search.widest);
  search.spots = distinct_spots(std::move(fitting), basis.gap, order);
  return search;
}

// The faces with a point within `radius` of one of `centres`.
std::vector<int> faces_near(const SurfaceMap& map, const std::vector<glm::dvec3>& centres, double radius) {
  std::vector<int> faces;
  for (int f = 0; f < map.mesh.face_count(); ++f) {
    const glm::ivec3 t = map.mesh.triangles[f];
    const glm::dvec3 a = map.mesh.positions[t.x], b = map.mesh.positions[t.y], c = map.mesh.positions[t.z];
    const glm::dvec3 centre = (a + b + c) / 3.0;
    const double size = std::max({glm::length(a - centre), glm::length(b - centre), glm::length(c - centre)});
    if (std::any_of(centres.begin(), centres.end(), [&](const glm::dvec3& p) { return glm::length(p - centre) <= radius + size; }))
      faces.push_back(f);
  }
  return faces;
}

}  // namespace

SpotSearch find_bare_spots(const SurfaceMap& map, const Elements& elements, const SpotBasis& basis, double slack,
                           SpotOrder order) {
  return search_faces(map, elements, basis, slack, {}, order);
}

namespace {

// Spots are closed down to this share of d below the spot stone: the search finds a spot's width
// to within a sample step (d / kSpotSamplesPerStone), and a spot it reads a little narrower than
// it is must close too.
constexpr double kCloseBelow = 1.0 / kSpotSamplesPerStone;
constexpr double kZone = 3.0;   // stones within this many d of a spot move to make room for it
// The last try for a spot the verdict counts: a vacancy (below) on the vase at 1.3 mm and in the
// vase band's adaptive pattern found its slack at 8 d, not at 5 d, nor at 5 d with four times the
// iterations.
constexpr double kWideZone = 8.0;
constexpr double kFrame = 2.0;  // and those within this many d + g beyond the zone hold it
constexpr int kRounds = 8;
constexpr int kSpotPackIterations = 600;
constexpr int kAttempts = 5;
// A packing whose overlaps sum to less than this share of d is settled on, up to this many rounds.
constexpr double kNearMiss = 0.02;
constexpr int kSettleRounds = 2;
constexpr double kPackAim = 1e-4;  // relative: beyond float32 rounding, far below what an eye sees
// A zone no stone can be pushed into is pushed apart to these multiples of the contact rule
// instead, the gentlest first (a push too strong for the frame jams the zone).
constexpr double kSpread[] = {1.01, 1.02, 1.035, 1.05, 1.08, 1.12};

// Whether the verdict counts a spot found `slack` narrower than its spot stone (SpotBasis).
bool verdict_counts(const BareSpot& s, double slack) { return s.fits >= s.wanted + slack; }

// Stones of the design's size that may move: the V-elements of diameter d.
bool movable_stone(const Elements& e, int i, double stone) {
  return e.kind[i] == ElementKind::Vertex && std::abs(e.diameter[i] - stone) <= 1e-9 * stone;
}

// The stones around a round's spots, and a new stone in each spot: packed together by contact on
// the surface (the zone's stones moving, the frame's holding), then every new stone that still
// breaks the contact rule or the margin taken out again.
class ZonePacking {
public:
  ZonePacking(const SurfaceMap& map, Elements& elements, const ElementsDesign& spec, const SpotBasis& basis,
              const BoundaryIndex& boundary, bool hold_rows, const std::vector<char>* held, double zone = kZone)
      : map_(map), e_(elements), spec_(spec), basis_(basis), boundary_(boundary), hold_rows_(hold_rows), held_(held),
        zone_(zone) {}

  // Returns the stones added, and through `shared` whether the zone was spread out instead.
  int close(const std::vector<BareSpot>& spots, bool& shared) {
    gather(spots);
    const int added = insert_and_pack();
    shared = added == 0 && share_out(spots);
    return added;
  }

private:
  struct Packed {
    std::vector<std::size_t> used;  // members taking part
    std::vector<glm::dvec2> uv;
    LiftedPoints lifted;
    std::vector<double> breach;
  };

  // The members taking part packed on the surface to `push` x the contact rule.
  Packed pack(bool with_new, double push) const {
    Packed p;
    for (std::size_t k = 0; k < member_.size(); ++k)
      if (member_[k] >= 0 || (with_new && in_[k])) p.used.push_back(k);
    std::vector<char> movable;
    for (std::size_t k : p.used) p.uv.push_back(uv_[k]), movable.push_back(movable_[k]);
    const double rule = contact_distance(basis_.stone, basis_.stone, basis_.gap);
    ContactPackingOptions options;
    // Pushed to a hair beyond the contact rule (or out by `push`), and settled at the rule itself:
    // the pavement's own pairs sit beyond it already and hold still.
    options.contact = rule * push * (1 + kPackAim);
    options.settled = push > 1 ? options.contact * (1 - kSettledOverlap) : rule * (1 + 0.1 * kPackAim);
    options.margin = (0.5 * basis_.stone + basis_.margin) * (1 + kPackAim);
    options.exact_margin = true;
    options.iterations = kSpotPackIterations;
    options.movable = &movable;
    options.boundary = &boundary_;
    pack_by_contact(map_, p.uv, options);
    // Spread out, the zone may press a stone against the held ones below the rule itself: settled
    // back to the rule from there, the spreading kept. A packing that came within a hair of the rule
    // is settled on for a few more rounds (a jammed zone is left as it is).
    options.contact = rule * (1 + kPackAim);
    options.settled = rule * (1 + 0.1 * kPackAim);
    if (push > 1) pack_by_contact(map_, p.uv, options);
    p.lifted.resize(p.uv.size());
    for (int settle = 0;; ++settle) {
      lift_points(map_, p.uv, p.lifted);
      p.breach = breaches(p.used, movable, p.lifted);
      const double total = std::accumulate(p.breach.begin(), p.breach.end(), 0.0);
      if (total == 0 || total > kNearMiss * basis_.stone || settle == kSettleRounds) break;
      pack_by_contact(map_, p.uv, options);
    }
    return p;
  }

  // A new stone in every spot, packed with the zone; one that leaves a pair breaking the contact
  // rule or a stone the margin is tried again without the new stones most to blame, from the same
  // start. Returns the stones added.
  int insert_and_pack() {
    for (int attempt = 0; attempt < kAttempts; ++attempt) {
      const Packed p = pack(true, 1);
      if (std::all_of(p.breach.begin(), p.breach.end(), [](double b) { return b == 0; })) return commit(p);
      // A stone of the pavement's own in a breach was pushed there by the new stone nearest it.
      std::vector<double> blame = p.breach;
      for (std::size_t k = 0; k < p.used.size(); ++k) {
        if (member_[p.used[k]] < 0 || p.breach[k] == 0) continue;
        std::size_t nearest = p.used.size();
        double best = zone_ * basis_.stone;
        for (std::size_t j = 0; j < p.used.size(); ++j)
          if (member_[p.used[j]] < 0 && glm::length(p.lifted.position[j] - p.lifted.position[k]) < best)
            best = glm::length(p.lifted.position[j] - p.lifted.position[k]), nearest = j;
        if (nearest < p.used.size()) blame[nearest] += p.breach[k];
      }
      // The new stones to blame, the most first: the upper half leave.
      std::vector<std::size_t> blamed;
      for (std::size_t k = 0; k < p.used.size(); ++k)
        if (member_[p.used[k]] < 0 && blame[k] > 0) blamed.push_back(k);
      if (blamed.empty()) return 0;  // the pavement's own stones were jammed: leave the zone as it was
      std::sort(blamed.begin(), blamed.end(), [&](std::size_t a, std::size_t b) { return blame[a] > blame[b]; });
      for (std::size_t r = 0; r < std::max<std::size_t>(1, blamed.size() / 2); ++r) in_[p.used[blamed[r]]] = 0;
    }
    return 0;
  }

  // Where no stone can be pushed in, the room is shared out: the zone's stones pushed apart by a
  // little more than contact, into the spots, until no place there keeps room for another stone.
  bool share_out(const std::vector<BareSpot>& spots) {
    std::vector<glm::dvec3> centres;
    for (const BareSpot& s : spots) centres.push_back(s.position);
    const std::vector<int> faces = faces_near(map_, centres, zone_ * basis_.stone);
    std::optional<Elements> uncounted;  // a spread that leaves only spots the verdict does not count
    for (const double push : kSpread) {
      const Packed p = pack(false, push);
      if (std::any_of(p.breach.begin(), p.breach.end(), [](double b) { return b > 0; })) continue;
      Elements after = e_;
      apply(p, after);
      const std::vector<BareSpot> left = search_faces(map_, after, basis_, kCloseBelow * basis_.stone, faces).spots;
      if (left.empty()) {
        e_ = std::move(after);
        return true;
      }
      if (!uncounted && std::none_of(left.begin(), left.end(), [&](const BareSpot& s) { return verdict_counts(s, kCloseBelow * basis_.stone); }))
        uncounted = std::move(after);
    }
    if (!uncounted) return false;
    e_ = std::move(*uncounted);
    return true;
  }

  void gather(const std::vector<BareSpot>& spots) {
    const double zone = zone_ * basis_.stone, hold = zone + kFrame * (basis_.stone + basis_.gap);
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (const BareSpot& s : spots) lo = glm::min(lo, s.position), hi = glm::max(hi, s.position);
    std::vector<glm::dvec3> centres;
    for (const BareSpot& s : spots) centres.push_back(s.position);
    const PointHash near(centres, CellGrid(lo - glm::dvec3(hold), hi + glm::dvec3(hold), hold));
    for (int i = 0; i < int(e_.size()); ++i) {
      double nearest = std::numeric_limits<double>::infinity();
      near.for_each_near(e_.position[i], [&](int k) { nearest = std::min(nearest, glm::length(e_.position[i] - centres[k])); });
      if (nearest > hold) continue;
      member_.push_back(i);
      // A rim row holds, unless asked: pushed inward, its stones leave teeth of metal along the rim
      // (the ring band's rim metal p95 went from 0.19 d to 0.41 d when they moved).
      const bool on_row = hold_rows_ && spec_.rim_rows != RimRows::None && !is_atlas(map_) &&
                          boundary_.nearest(e_.position[i]).distance < boundary_.reach();
      const bool designers = held_ && std::size_t(i) < held_->size() && (*held_)[std::size_t(i)];
      movable_.push_back(nearest <= zone && movable_stone(e_, i, basis_.stone) && !on_row && !designers);
      uv_.push_back(e_.uv[i]);
    }
    for (const BareSpot& s : spots) member_.push_back(-1), movable_.push_back(1), uv_.push_back(s.uv);
    in_.assign(member_.size(), 1);
    is_member_.assign(e_.size(), 0);
    for (const int i : member_)
      if (i >= 0) is_member_[std::size_t(i)] = 1;
  }

  double diameter(std::size_t k) const { return member_[k] < 0 ? basis_.stone : e_.diameter[member_[k]]; }

  // Per member taking part: how far it breaks the contact rule (the overlaps summed, with the other
  // members at their new places and every other element at its own) or the margin (as much as a
  // zone), 0 when it breaks neither. Only moving members can.
  std::vector<double> breaches(const std::vector<std::size_t>& used, const std::vector<char>& movable,
                               const LiftedPoints& lifted) const {
    const std::size_t n = used.size();
    std::vector<double> breach(n, 0);
    const double reach = basis_.stone + basis_.gap;
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (const glm::dvec3& p : lifted.position) lo = glm::min(lo, p), hi = glm::max(hi, p);
    for (const glm::dvec3& p : e_.position) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const CellGrid grid(lo, hi, reach);
    const PointHash moved(lifted.position, grid);
    const PointHash others(e_.position, grid);
    for (std::size_t a = 0; a < n; ++a) {
      if (!movable[a]) continue;
      const std::size_t k = used[a];
      const bool strayed =
          lifted.triangle[a] < 0 ||
          (!is_atlas(map_) && !keeps_margin(boundary_.nearest(lifted.position[a]).distance, diameter(k), basis_.margin));
      if (strayed) breach[a] += kZone * basis_.stone;
      const auto against = [&](double d, double other_diameter) {
        return elements_collide(d, diameter(k), other_diameter, basis_.gap)
                   ? contact_distance(diameter(k), other_diameter, basis_.gap) - d
                   : 0.0;
      };
      moved.for_each_near(lifted.position[a], [&](int b) {
        if (std::size_t(b) == a || (movable[std::size_t(b)] && std::size_t(b) < a)) return;
        const double overlap =
            against(glm::length(lifted.position[a] - lifted.position[std::size_t(b)]), diameter(used[std::size_t(b)]));
        breach[a] += overlap, breach[std::size_t(b)] += overlap;
      });
      others.for_each_near(lifted.position[a], [&](int j) {
        if (is_member_[std::size_t(j)]) return;  // a member: at its new place, above
        breach[a] += against(glm::length(lifted.position[a] - e_.position[std::size_t(j)]), e_.diameter[std::size_t(j)]);
      });
    }
    return breach;
  }

  // The packed places written into `elements`, the new stones appended; returns how many.
  int apply(const Packed& p, Elements& elements) const {
    int added = 0;
    for (std::size_t a = 0; a < p.used.size(); ++a) {
      const int i = member_[p.used[a]];
      if (i < 0) {
        elements.push_back(ElementKind::Vertex, -1, 0, p.uv[a], p.lifted.position[a], p.lifted.normal[a], basis_.stone,
                           spec_.vertex.shape);
        ++added;
      } else if (movable_[p.used[a]]) {
        elements.uv[i] = p.uv[a], elements.position[i] = p.lifted.position[a], elements.normal[i] = p.lifted.normal[a];
      }
    }
    return added;
  }
  int commit(const Packed& p) { return apply(p, e_); }

  const SurfaceMap& map_;
  Elements& e_;
  const ElementsDesign& spec_;
  const SpotBasis& basis_;
  const BoundaryIndex& boundary_;
  bool hold_rows_;
  const std::vector<char>* held_;
  double zone_;
  std::vector<int> member_;  // element index, -1 for a new stone
  std::vector<char> movable_;
  std::vector<glm::dvec2> uv_;
  std::vector<char> in_;  // a new stone still tried
  std::vector<char> is_member_;  // per element
};

// The spots a whole stone fits in get one each, no two closer than the contact rule allows;
// returns the spots left (narrower than a stone, or too near one just put in).
std::vector<BareSpot> insert_where_stones_fit(const SurfaceMap& map, Elements& elements, const ElementsDesign& spec,
                                             const SpotBasis& basis, const std::vector<BareSpot>& spots, int& added) {
  std::vector<BareSpot> left;
  std::vector<glm::dvec3> put;
  for (const BareSpot& s : spots) {
    const bool clear = std::none_of(put.begin(), put.end(), [&](const glm::dvec3& p) {
      return elements_collide(glm::length(p - s.position), basis.stone, basis.stone, basis.gap);
    });
    if (s.fits < basis.stone * (1 + 1e-9) || !clear) {
      left.push_back(s);
      continue;
    }
    LiftedPoints lifted;
    lifted.resize(1);
    lift_points(map, std::span<const glm::dvec2>(&s.uv, 1), lifted);
    if (lifted.triangle[0] < 0) continue;
    elements.push_back(ElementKind::Vertex, -1, 0, s.uv, lifted.position[0], lifted.normal[0], basis.stone,
                       spec.vertex.shape);
    put.push_back(lifted.position[0]);
    ++added;
  }
  return left;
}

// The spots in groups: two nearer than `apart` are in one group.
std::vector<std::vector<BareSpot>> clusters(const std::vector<BareSpot>& spots, double apart) {
  std::vector<int> group(spots.size(), -1);
  int groups = 0;
  for (std::size_t s = 0; s < spots.size(); ++s) {
    if (group[s] >= 0) continue;
    group[s] = groups;
    for (std::vector<std::size_t> open{s}; !open.empty();) {
      const std::size_t a = open.back();
      open.pop_back();
      for (std::size_t b = 0; b < spots.size(); ++b)
        if (group[b] < 0 && glm::length(spots[a].position - spots[b].position) < apart) group[b] = groups, open.push_back(b);
    }
    ++groups;
  }
  std::vector<std::vector<BareSpot>> out(static_cast<std::size_t>(groups));
  for (std::size_t s = 0; s < spots.size(); ++s) out[std::size_t(group[s])].push_back(spots[s]);
  return out;
}

}  // namespace

SpotClosing close_bare_spots(const SurfaceMap& map, Elements& elements, const ElementsDesign& spec, double spacing,
                             const SpotBasis& basis, const std::atomic<bool>* stop, const std::vector<char>* held) {
  const Stopwatch watch;
  SpotClosing report;
  if (!spec.vertex.enabled || spec.allow_overlap || !(basis.stone > 0) || !(spacing > 0)) return report;
  const double slack = kCloseBelow * basis.stone;
  // The packing keeps stones off the rims by their radius and the margin: an index reaching just
  // that far answers fastest.
  const BoundaryIndex boundary(map.mesh, 1.1 * (0.5 * basis.stone + basis.margin) + 1e-9 * basis.stone);
  // What the closing may never do is break the contact rule: checked over all pairs at the end,
  // and the elements put back as they were if it did (a bug, said by the figures staying as before).
  const Elements before = elements;
  const std::size_t collisions_before = find_collisions(elements, basis.gap).size();
  std::vector<glm::dvec3> failed;
  for (; report.rounds < kRounds && !(stop && stop->load()); ++report.rounds) {
    const SpotSearch search = find_bare_spots(map, elements, basis, slack);
    if (search.spots.empty()) break;
    int added = 0, changed = 0;
    const std::vector<BareSpot> narrow = insert_where_stones_fit(map, elements, spec, basis, search.spots, added);
    changed += added;
    // Across a closed surface's charts the seams hold the stones: no pushing there.
    // Each cluster of narrow spots packed on its own: what happens to one cannot reach another
    // (an edit far away leaves these as they were).
    // A spot that could not be pushed into is not tried again (nothing near it changes in a later
    // round but what a round closes elsewhere).
    std::vector<BareSpot> open;
    for (const BareSpot& s : narrow)
      if (std::none_of(failed.begin(), failed.end(),
                       [&](const glm::dvec3& p) { return glm::length(p - s.position) < basis.stone; }))
        open.push_back(s);
    if (!is_atlas(map))
      for (const std::vector<BareSpot>& cluster : clusters(open, kZone * basis.stone + kFrame * (basis.stone + basis.gap))) {
        bool shared = false;
        int pushed = ZonePacking(map, elements, spec, basis, boundary, true, held).close(cluster, shared);
        // The rim rows move only for a spot the verdict counts (one the rows held left open):
        // pushing them for the narrower ones the closing also takes bent the ring band's rims.
        if (pushed == 0 && !shared) {
          std::vector<BareSpot> counted;
          for (const BareSpot& s : cluster)
            if (verdict_counts(s, slack)) counted.push_back(s);
          if (!counted.empty())
            pushed = ZonePacking(map, elements, spec, basis, boundary, false, held).close(counted, shared);
          // A vacancy in a lattice at contact: its six neighbours cannot close in on it (they would
          // touch each other first), and a stone pushed in needs the slack of a wider zone.
          if (!counted.empty() && pushed == 0 && !shared)
            pushed = ZonePacking(map, elements, spec, basis, boundary, false, held, kWideZone).close(counted, shared);
        }
        added += pushed;
        report.pushed += pushed;
        report.shared += shared;
        changed += pushed > 0 || shared;
        // Spread out, a zone may keep spots narrower than the verdict counts: they are not tried
        // again either (each round spread the vase's same six again, 0.24 s a round).
        if (pushed == 0)
          for (const BareSpot& s : cluster) failed.push_back(s.position);
      }
    report.added += added;
    if (changed == 0) break;
  }
  if (report.added > 0 && find_collisions(elements, basis.gap).size() > collisions_before) {
    elements = before;
    report = SpotClosing{};
  }
  report.milliseconds = watch.milliseconds();
  return report;
}

}  // namespace paver
