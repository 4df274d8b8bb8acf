#include "elements/beads.h"
#include "design/design_keys.h"

#include "core/number_text.h"
#include "core/point_hash.h"
#include "elements/element_frame.h"
#include "map/boundary_index.h"
#include "map/lifting.h"

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <vector>

namespace paver {
namespace {

// Around a stone that needs holders, beads are tried every 360 / kBeadDirections degrees.
constexpr int kBeadDirections = 48;

struct Placer {
  // `grid` covers the stones and every bead near them, its cells as wide as a search reaches.
  Placer(const SurfaceMap& surface, const Elements& placed, const ElementsDesign& spec, const CellGrid& grid)
      : map(surface), stones(placed), design(spec), stone_hash(placed.position, grid),
        bead_hash(beads.position, grid, PointHash::Fill::None), holders(placed.size(), 0) {}

  const SurfaceMap& map;
  const Elements& stones;
  const ElementsDesign& design;
  PointHash stone_hash;
  std::optional<BoundaryIndex> rims;
  Elements beads;
  PointHash bead_hash;  // over beads.position, each inserted as it is placed
  std::vector<int> holders;  // #stones

  bool holds(int s, const glm::dvec3& p, double diameter) const {
    const double d = stones.diameter[std::size_t(s)];
    return glm::length(p - stones.position[std::size_t(s)]) <= 0.5 * (d + diameter) + kBeadHoldSlack * d;
  }

  // A bead of `diameter` at p keeps off every table, clear of every bead by the gap, on the metal.
  bool fits(const glm::dvec3& p, double diameter) const {
    bool clear = true;
    stone_hash.for_each_near(p, [&](int s) {
      const double d = stones.diameter[std::size_t(s)];
      const double into = 0.5 * (d + diameter) - glm::length(p - stones.position[std::size_t(s)]);
      clear = clear && into <= kTableShare * d;
    });
    if (!clear) return false;
    bead_hash.for_each_near(p, [&](int b) {
      clear = clear && glm::length(p - beads.position[std::size_t(b)]) >=
                           0.5 * (diameter + beads.diameter[std::size_t(b)]) + design.gap;
    });
    return clear && (!rims || rims->nearest(p).distance >= 0.5 * diameter);
  }

  void add(int holding, glm::dvec2 uv, const glm::dvec3& p, const glm::dvec3& n, double diameter) {
    beads.push_back(ElementKind::Bead, holding, 0, uv, p, n, diameter, ShapeKind::Sphere);
    bead_hash.insert(int(beads.size()) - 1);
    stone_hash.for_each_near(p, [&](int s) {
      if (holds(s, p, diameter)) ++holders[std::size_t(s)];
    });
  }
};

double bead_size(const ElementsDesign& design, double room) {
  return std::max({design.beads.min_diameter, 2 * (room + design.beads.over), 2 * room * design.beads.scale});
}

// Every triangle of mutual contacts once (i < j < k), its bead under the centres' middle.
void triangle_beads(Placer& placer) {
  const Elements& stones = placer.stones;
  const double gap = placer.design.gap;
  const auto in_contact = [&](int i, int j) {
    const double di = stones.diameter[std::size_t(i)], dj = stones.diameter[std::size_t(j)];
    return glm::length(stones.position[std::size_t(i)] - stones.position[std::size_t(j)]) <=
           0.5 * (di + dj) + gap + kBeadContactSlack * std::min(di, dj);
  };
  std::vector<std::vector<int>> neighbours(stones.size());
  for (int i = 0; i < int(stones.size()); ++i)
    placer.stone_hash.for_each_near(stones.position[std::size_t(i)], [&](int j) {
      if (j != i && in_contact(i, j)) neighbours[std::size_t(i)].push_back(j);
    });
  for (auto& list : neighbours) std::sort(list.begin(), list.end());
  std::vector<std::array<int, 3>> triangles;
  std::vector<glm::dvec2> middles;
  for (int i = 0; i < int(stones.size()); ++i)
    for (const int j : neighbours[std::size_t(i)]) {
      if (j <= i) continue;
      for (const int k : neighbours[std::size_t(j)]) {
        if (k <= j || !std::binary_search(neighbours[std::size_t(i)].begin(), neighbours[std::size_t(i)].end(), k))
          continue;
        triangles.push_back({i, j, k});
        const glm::dvec2 a = stones.uv[std::size_t(i)];  // the other two in one piece with it, across a seam
        middles.push_back((a + nearest_image(placer.map, stones.uv[std::size_t(j)], a) +
                           nearest_image(placer.map, stones.uv[std::size_t(k)], a)) / 3.0);
      }
    }
  LiftedPoints lifted;
  lifted.resize(middles.size());
  lift_points(placer.map, middles, lifted);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    if (lifted.triangle[t] < 0) continue;
    double room = std::numeric_limits<double>::infinity();  // the largest free radius at the bead
    for (const int s : triangles[t])
      room = std::min(room, glm::length(lifted.position[t] - stones.position[std::size_t(s)]) -
                                0.5 * stones.diameter[std::size_t(s)]);
    if (!(room > 0)) continue;
    const double diameter = bead_size(placer.design, room);
    if (placer.fits(lifted.position[t], diameter))
      placer.add(triangles[t][0], middles[t], lifted.position[t], lifted.normal[t], diameter);
  }
}

// The map step that moves a point at `uv` by the tangent vector `step` in 3D (the triangle's own
// linear map, least squares in its plane); nothing when uv is off the map.
std::optional<glm::dvec2> uv_step(const SurfaceMap& map, glm::dvec2 uv, const glm::dvec3& step) {
  glm::dvec3 bary;
  const int t = locate_on_map(map, uv, bary);
  if (t < 0) return std::nullopt;
  const glm::ivec3 tri = map.mesh.triangles[std::size_t(t)];
  const std::array<glm::dvec2, 3> corner = triangle_uv(map, t);
  const glm::dvec3 e1 = map.mesh.positions[std::size_t(tri.y)] - map.mesh.positions[std::size_t(tri.x)];
  const glm::dvec3 e2 = map.mesh.positions[std::size_t(tri.z)] - map.mesh.positions[std::size_t(tri.x)];
  const double a = glm::dot(e1, e1), b = glm::dot(e1, e2), c = glm::dot(e2, e2);
  const double det = a * c - b * b;
  if (!(det > 0)) return std::nullopt;
  const double r1 = glm::dot(step, e1), r2 = glm::dot(step, e2);
  const double x = (c * r1 - b * r2) / det, y = (a * r2 - b * r1) / det;
  return uv + x * (corner[1] - corner[0]) + y * (corner[2] - corner[0]);
}

// The stone's holders' directions around it, in its frame (radians).
std::vector<double> holder_angles(const Placer& placer, int s, const ElementFrame& frame) {
  std::vector<double> angles;
  const glm::dvec3 centre = placer.stones.position[std::size_t(s)];
  placer.bead_hash.for_each_near(centre, [&](int b) {
    const glm::dvec3 p = placer.beads.position[std::size_t(b)];
    if (!placer.holds(s, p, placer.beads.diameter[std::size_t(b)])) return;
    angles.push_back(std::atan2(glm::dot(p - centre, frame.b), glm::dot(p - centre, frame.t)));
  });
  return angles;
}

// The widest angle around a stone with no holder (radians): 2 pi with none.
double widest_open(std::vector<double> angles) {
  if (angles.empty()) return 2 * std::numbers::pi;
  std::sort(angles.begin(), angles.end());
  double open = angles.front() + 2 * std::numbers::pi - angles.back();
  for (std::size_t k = 1; k < angles.size(); ++k) open = std::max(open, angles[k] - angles[k - 1]);
  return open;
}

bool needs_holders(const std::vector<double>& held) {
  return int(held.size()) < kBeadsPerStone || widest_open(held) > kWidestOpenDeg * std::numbers::pi / 180;
}

double angle_apart(double a, double b) {
  const double d = std::fmod(std::abs(a - b), 2 * std::numbers::pi);
  return std::min(d, 2 * std::numbers::pi - d);
}

// Beads of its own for every stone with fewer than kBeadsPerStone holders: around its girdle,
// reaching `over` over it, the candidate farthest in angle from its holders first (and, of two
// alike, the one that holds more stones still short of holders).
void own_beads(Placer& placer) {
  const Elements& stones = placer.stones;
  const ElementsDesign& design = placer.design;
  for (int s = 0; s < int(stones.size()); ++s) {
    if (!needs_holders(holder_angles(placer, s, element_frame(stones.normal[std::size_t(s)])))) continue;
    const double d = stones.diameter[std::size_t(s)], diameter = bead_size(design, 0);
    const ElementFrame frame = element_frame(stones.normal[std::size_t(s)]);
    const double along = 0.5 * (d + diameter) - design.beads.over;
    std::vector<glm::dvec2> uv;
    for (int k = 0; k < kBeadDirections; ++k) {
      const double a = 2 * std::numbers::pi * k / kBeadDirections;
      if (const auto moved = uv_step(placer.map, stones.uv[std::size_t(s)],
                                     along * (std::cos(a) * frame.t + std::sin(a) * frame.b)))
        uv.push_back(*moved);
    }
    LiftedPoints lifted;
    lifted.resize(uv.size());
    lift_points(placer.map, uv, lifted);
    for (std::vector<double> held = holder_angles(placer, s, frame); needs_holders(held);
         held = holder_angles(placer, s, frame)) {
      int best = -1;
      double best_score = -1;
      for (std::size_t c = 0; c < uv.size(); ++c) {
        const glm::dvec3 p = lifted.position[c];
        if (lifted.triangle[c] < 0 || !placer.holds(s, p, diameter) || !placer.fits(p, diameter)) continue;
        const glm::dvec3 r = p - stones.position[std::size_t(s)];
        const double angle = std::atan2(glm::dot(r, frame.b), glm::dot(r, frame.t));
        double score = std::numbers::pi;
        for (const double h : held) score = std::min(score, angle_apart(angle, h));
        placer.stone_hash.for_each_near(p, [&](int o) {
          if (o != s && placer.holders[std::size_t(o)] < kBeadsPerStone && placer.holds(o, p, diameter)) score += 0.25;
        });
        if (score > best_score) best = int(c), best_score = score;
      }
      if (best < 0) break;  // no room left around this stone
      placer.add(s, uv[std::size_t(best)], lifted.position[std::size_t(best)], lifted.normal[std::size_t(best)],
                 diameter);
    }
  }
}

CellGrid stone_cells(const Elements& stones, double reach) {
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (const glm::dvec3& p : stones.position) lo = glm::min(lo, p), hi = glm::max(hi, p);
  return CellGrid(lo - glm::dvec3(reach), hi + glm::dvec3(reach), reach);
}

double largest_of(const Elements& stones) {
  double largest = 0;
  for (const double d : stones.diameter) largest = std::max(largest, d);
  return largest;
}

}  // namespace

Elements place_beads(const SurfaceMap& map, const Elements& stones, const ElementsDesign& design) {
  if (!design.beads.enabled || stones.size() == 0) return Elements{};
  const double largest = largest_of(stones);
  // A bead four times the largest stone reaches past every table it touches: none can be placed
  // (the warning says so), and its reach would make every search visit every stone.
  if (!(design.beads.min_diameter <= 4 * largest)) return Elements{};
  const double reach = largest * (1 + kBeadContactSlack) + design.gap + std::max(design.beads.min_diameter, largest);
  Placer placer(map, stones, design, stone_cells(stones, reach));
  if (!is_atlas(map)) placer.rims.emplace(map.mesh, reach);
  triangle_beads(placer);
  own_beads(placer);
  return std::move(placer.beads);
}

BeadHold measure_bead_hold(const Elements& stones, const Elements& beads) {
  BeadHold hold;
  hold.holders.assign(stones.size(), 0);
  hold.widest_open_deg.assign(stones.size(), 360);
  hold.least_bead_clearance = std::numeric_limits<double>::infinity();
  const double largest = std::max(largest_of(stones), largest_of(beads));
  if (stones.size() == 0) return hold;
  const double reach = 2 * largest;
  const PointHash bead_hash(beads.position, stone_cells(stones, reach));
  std::vector<std::vector<double>> angles(stones.size());
  for (std::size_t s = 0; s < stones.size(); ++s) {
    const ElementFrame frame = element_frame(stones.normal[s]);
    bead_hash.for_each_near(stones.position[s], [&](int b) {
      const glm::dvec3 r = beads.position[std::size_t(b)] - stones.position[s];
      const double d = stones.diameter[s], into = 0.5 * (d + beads.diameter[std::size_t(b)]) - glm::length(r);
      if (into > kTableShare * d + 1e-12) ++hold.over_tables;
      if (into < -kBeadHoldSlack * d) return;
      ++hold.holders[s];
      angles[s].push_back(std::atan2(glm::dot(r, frame.b), glm::dot(r, frame.t)) * 180 / std::numbers::pi);
    });
    std::sort(angles[s].begin(), angles[s].end());
    for (std::size_t k = 0; k < angles[s].size(); ++k) {
      const double next = k + 1 < angles[s].size() ? angles[s][k + 1] : angles[s][0] + 360;
      hold.widest_open_deg[s] = k == 0 ? next - angles[s][k] : std::max(hold.widest_open_deg[s], next - angles[s][k]);
    }
    if (hold.holders[s] < kBeadsPerStone || hold.widest_open_deg[s] > kWidestOpenDeg + 1e-9)
      hold.underheld.push_back(int(s));
  }
  for (std::size_t b = 0; b < beads.size(); ++b)
    bead_hash.for_each_near(beads.position[b], [&](int o) {
      if (std::size_t(o) <= b) return;
      hold.least_bead_clearance =
          std::min(hold.least_bead_clearance, glm::length(beads.position[b] - beads.position[std::size_t(o)]) -
                                                  0.5 * (beads.diameter[b] + beads.diameter[std::size_t(o)]));
    });
  return hold;
}

nlohmann::json bead_hold_json(const Elements& stones, const Elements& beads, const ElementsDesign& design, Units units) {
  nlohmann::json j = {{"enabled", design.beads.enabled}};
  if (!design.beads.enabled) return j;
  const double mm = millimetres_per_unit(units);
  double smallest = 0, largest = 0;
  if (beads.size() > 0) {
    smallest = *std::min_element(beads.diameter.begin(), beads.diameter.end()) * mm;
    largest = *std::max_element(beads.diameter.begin(), beads.diameter.end()) * mm;
  }
  const BeadHold hold = measure_bead_hold(stones, beads);
  int least = stones.size() > 0 ? std::numeric_limits<int>::max() : 0;
  double open = 0;
  for (std::size_t s = 0; s < stones.size(); ++s) {
    least = std::min(least, hold.holders[s]);
    open = std::max(open, hold.widest_open_deg[s]);
  }
  j["scale"] = design.beads.scale;
  j["min_diameter"] = design.beads.min_diameter;
  j["over"] = design.beads.over;
  j["count"] = beads.size();
  j["diameter_mm_min"] = smallest;
  j["diameter_mm_max"] = largest;
  j["holders_least"] = least;
  j["stones_underheld"] = hold.underheld.size();
  j["widest_open_deg"] = open;
  j["least_bead_clearance"] = std::isfinite(hold.least_bead_clearance) ? nlohmann::json(hold.least_bead_clearance)
                                                                       : nlohmann::json(nullptr);
  j["over_tables"] = hold.over_tables;
  return j;
}

std::optional<std::string> fine_beads_warning(const Elements& beads, Units units) {
  const double mm = millimetres_per_unit(units);
  std::size_t fine = 0;
  double smallest = std::numeric_limits<double>::infinity();
  for (const double d : beads.diameter) {
    smallest = std::min(smallest, d * mm);
    if (d * mm < kFinestCastBeadMm) ++fine;
  }
  if (fine == 0) return std::nullopt;
  return std::to_string(fine) + " of " + std::to_string(beads.size()) + " beads are under " +
         number_text(kFinestCastBeadMm) + " mm (the smallest " + number_text(std::round(smallest * 1000) / 1000) +
         " mm), finer than casting or wax printing holds reliably: raise " + key_path(Key::beads_min_diameter);
}

std::optional<std::string> underheld_stones_warning(const Elements& stones, const BeadHold& hold) {
  if (hold.underheld.empty()) return std::nullopt;
  std::string ids;
  for (std::size_t k = 0; k < std::min<std::size_t>(hold.underheld.size(), 8); ++k)
    ids += (k ? ", " : "") + std::to_string(stones.id[std::size_t(hold.underheld[k])]);
  if (hold.underheld.size() > 8) ids += ", ...";
  const bool one = hold.underheld.size() == 1;
  return std::to_string(hold.underheld.size()) + (one ? " stone is" : " stones are") + " not held all round (" +
         std::to_string(kBeadsPerStone) + " beads or more, no side open wider than " + number_text(kWidestOpenDeg) +
         " degrees; " + (one ? "id " : "ids ") + ids + "): no bead fits beside " + (one ? "it" : "them") +
         " on the metal; widen the margin (" +
         key_path(Key::margin) + ") or lower " + key_path(Key::beads_min_diameter);
}

}  // namespace paver
