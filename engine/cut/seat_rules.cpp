#include "cut/seat_rules.h"

#include "core/number_text.h"
#include "core/point_hash.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <limits>

namespace paver {
namespace {

// How far a stone's shape reaches below and above its girdle's middle, in units of its diameter.
struct ShapeReach {
  double below = 0, above = 0;
};

ShapeReach reach_of(const ShapeMesh& shape) {
  ShapeReach r;
  for (const glm::vec3& v : shape.positions) {
    r.below = std::max(r.below, -double(v.z));
    r.above = std::max(r.above, double(v.z));
  }
  return r;
}

// Every stone that breaks a rule, the worst value found: the least, or for a ceiling the greatest.
void note_break(std::vector<SeatRuleBreak>& breaks, const char* rule, double limit, double value, int id,
                bool ceiling = false) {
  auto it = std::find_if(breaks.begin(), breaks.end(), [&](const SeatRuleBreak& b) { return b.rule == rule; });
  if (it == breaks.end()) it = breaks.insert(breaks.end(), SeatRuleBreak{rule, limit, value, {}});
  it->worst = ceiling ? std::max(it->worst, value) : std::min(it->worst, value);
  it->stone_ids.push_back(id);  // made unique once, at the end
}

}  // namespace

SeatCheck check_seats(const Elements& paved, const ShapeTable& shapes, CutterKind cutter, double thickness,
                      const FingerSide* ring, const SeatRules& rules, double seat_depth) {
  const Elements stones = seated_stones(paved, seat_depth);
  SeatCheck check;
  check.seat_depth = seat_depth;
  check.least_culet_metal = check.least_seat_wall = check.lowest_table = std::numeric_limits<double>::infinity();
  if (stones.size() == 0) return check;
  const double widening = cutter == CutterKind::Seat ? 2 * kSeatClearance : 0;  // of d, across the girdle
  double largest = 0;
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < stones.size(); ++i) {
    largest = std::max(largest, stones.diameter[i]);
    lo = glm::min(lo, stones.position[i]);
    hi = glm::max(hi, stones.position[i]);
  }
  const double reach = (1 + widening) * largest + rules.seat_wall.value_or(0) + largest;
  const PointHash near(stones.position, CellGrid(lo - glm::dvec3(reach), hi + glm::dvec3(reach), reach));
  for (std::size_t i = 0; i < stones.size(); ++i) {
    const double d = stones.diameter[i];
    const ShapeReach shape = reach_of(shapes[stones.shape[i]]);
    const double table = shape.above * d - seat_depth;
    check.highest_table = std::max(check.highest_table, table);
    check.lowest_table = std::min(check.lowest_table, table);
    if (table < 0) note_break(check.breaks, "table below the metal", 0, table, stones.id[i]);
    if (rules.table_height && table > *rules.table_height)
      note_break(check.breaks, "table height", *rules.table_height, table, stones.id[i], true);
    const glm::dvec3 culet = stones.position[i] - shape.below * d * stones.normal[i];
    const double metal =
        ring ? distance_from_axis(ring->axis, culet) - ring->inside_radius : thickness - shape.below * d - seat_depth;
    check.least_culet_metal = std::min(check.least_culet_metal, metal);
    if (rules.culet_clearance && metal < *rules.culet_clearance)
      note_break(check.breaks, "culet clearance", *rules.culet_clearance, metal, stones.id[i]);
    near.for_each_near(stones.position[i], [&](int j) {
      if (std::size_t(j) <= i) return;
      const double wall = glm::length(stones.position[i] - stones.position[std::size_t(j)]) -
                          0.5 * (1 + widening) * (d + stones.diameter[std::size_t(j)]);
      check.least_seat_wall = std::min(check.least_seat_wall, wall);
      if (rules.seat_wall && wall < *rules.seat_wall) {
        note_break(check.breaks, "seat wall", *rules.seat_wall, wall, stones.id[i]);
        note_break(check.breaks, "seat wall", *rules.seat_wall, wall, stones.id[std::size_t(j)]);
      }
    });
  }
  for (SeatRuleBreak& b : check.breaks) {
    std::sort(b.stone_ids.begin(), b.stone_ids.end());
    b.stone_ids.erase(std::unique(b.stone_ids.begin(), b.stone_ids.end()), b.stone_ids.end());
  }
  return check;
}

nlohmann::json seat_check_json(const SeatCheck& check) {
  const auto finite = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); };
  nlohmann::json breaks = nlohmann::json::array();
  for (const SeatRuleBreak& b : check.breaks)
    breaks.push_back({{"rule", b.rule}, {"limit", b.limit}, {"worst", b.worst}, {"stones", b.stone_ids}});
  return {{"least_culet_metal", finite(check.least_culet_metal)},
          {"least_seat_wall", finite(check.least_seat_wall)},
          {"highest_table", check.highest_table},
          {"lowest_table", finite(check.lowest_table)},
          {"seat_depth", check.seat_depth},
          {"broken", breaks}};
}

std::vector<std::string> seat_rule_problems(const SeatCheck& check) {
  std::vector<std::string> problems;
  for (const SeatRuleBreak& b : check.breaks) {
    std::string ids;
    for (std::size_t k = 0; k < std::min<std::size_t>(b.stone_ids.size(), 10); ++k)
      ids += (k ? ", " : "") + std::to_string(b.stone_ids[k]);
    if (b.stone_ids.size() > 10) ids += ", ...";
    const std::string count = std::to_string(b.stone_ids.size()) + (b.stone_ids.size() == 1 ? " stone" : " stones");
    const std::string limit = significant_text(b.limit, 3), worst = significant_text(b.worst, 3);
    const std::string have = b.stone_ids.size() == 1 ? " has" : " have";
    if (b.rule == "culet clearance")
      problems.push_back(count + " leave less than " + limit + " of metal under their culets (--culet-clearance; the least " +
                         worst + "; ids " + ids + "): thicken the metal, set them less deep or use smaller stones there");
    else if (b.rule == "seat wall")
      problems.push_back(count + " stand with less than " + limit + " of metal between their seats (--seat-wall; the least " +
                         worst + "; ids " + ids + "): widen the gap or use smaller stones there");
    else if (b.rule == "table height")
      problems.push_back(count + have + " tables more than " + limit + " above the metal (--table-height; the highest " +
                         worst + "; ids " + ids + "): set them deeper (--seat-depth) or use smaller stones there");
    else
      problems.push_back(count + have + " tables below the metal (--seat-depth; the lowest " + worst + "; ids " + ids +
                         "): set them less deep, at most their crown's height");
  }
  return problems;
}

}  // namespace paver
