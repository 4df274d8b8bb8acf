#pragma once
// Production rules of the cut metal (issue 43), as a setter and a caster check them before they
// accept a piece: how much metal is left under each stone's culet (toward a ring's finger), how
// much metal stands between two seats at their girdles, and how high each stone's table stands
// above the metal. A rule the user sets that a stone breaks makes the run NOT OK, naming the
// stones; the figures are reported either way.
#include "cut/finger_side.h"
#include "cut/seat_cutter.h"
#include "elements/elements.h"
#include "elements/element_shape.h"
#include "io/shape_table.h"

#include <nlohmann/json_fwd.hpp>

#include <optional>
#include <string>
#include <vector>

namespace paver {

struct SeatRules {
  std::optional<double> culet_clearance;  // metal left under every culet, at least (surface units)
  std::optional<double> seat_wall;        // metal between two seats at their girdles, at least
  std::optional<double> table_height;     // a table above the metal's surface, at most
};


struct SeatRuleBreak {
  std::string rule;            // "culet clearance", "seat wall", "table height", "table below the metal"
  double limit = 0;            // as set
  double worst = 0;            // the least found (for table height, the greatest)
  std::vector<int> stone_ids;  // every stone that breaks it, by id
};

struct SeatCheck {
  double least_culet_metal = 0;   // the least metal under a culet (negative: it stands out behind)
  double least_seat_wall = 0;     // the least metal between two seats' girdles (negative: they run together)
  double highest_table = 0;       // a table's greatest height above the surface the stones sit on
  double lowest_table = 0;        // and its least (negative: sunk below the metal, never settable)
  double seat_depth = 0;          // how deep the stones were set
  std::vector<SeatRuleBreak> breaks;
};

// Inputs: the stones (numbered) as paved, set `seat_depth` below the surface (seated_stones), their
// shapes, the cutter kind (a seat's girdle is kSeatClearance wider than the stone), the metal:
// `thickness` behind the surface, or a ring's finger side when `ring` is given; the rules. Stones
// are checked in 3D against every near neighbour. A table sunk below the metal always breaks
// ("table below the metal"): no setter can set it.
SeatCheck check_seats(const Elements& stones, const ShapeTable& shapes, CutterKind cutter, double thickness,
                      const FingerSide* ring, const SeatRules& rules, double seat_depth = 0);

// report.json's cut.seats: the figures and each broken rule with its stones.
nlohmann::json seat_check_json(const SeatCheck& check);

// The verdict's lines for the broken rules: "12 stones have less than 0.2 of metal under their
// culets (the least 0.05; ids 3, 17, ...): ...".
std::vector<std::string> seat_rule_problems(const SeatCheck& check);

}  // namespace paver
