#pragma once
// The bill of stones: how many elements of each shape and size a pavement holds, in millimetres,
// and for round brilliants (the gem shape) their weight in carats: what a jeweller orders from.
// Written as stones.csv and into report.json (`stones`).
#include "design/design.h"
#include "elements/elements.h"

#include <nlohmann/json_fwd.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace paver {

struct StoneRow {
  ShapeKind shape;
  double diameter_mm;                 // to the micron: sizes that differ less are one row
  long count = 0;
  std::optional<double> carat_each;   // round brilliants only
  double carat_total = 0;             // 0 for shapes without carats
};

struct BillOfStones {
  Units units = Units::Millimetre;    // of the surface the sizes were converted from
  std::vector<StoneRow> rows;         // by shape, then by diameter
  long count = 0;
  double carat_total = 0;

  // Whether any row is weighed: a bill of spheres, discs or custom shapes has no total carats
  // (a "0 ct" would read as weightless stones).
  bool weighed() const;
};

// Carats as the trade writes them, in stones.csv, report.html and the studio alike: a stone's
// weight to 4 significant digits (melee weighs thousandths of a carat), totals to 0.0001 ct.
std::string carat_each_text(double carats);
std::string carat_total_text(double carats);

// A stone's diameter in mm as the bill gives it: two decimals, a third where the size has one
// (1.50, 1.015), never rounded to a size it is not.
std::string diameter_mm_text(double diameter_mm);

// Groups `elements` by shape and diameter (converted to mm from `units`, to the micron).
BillOfStones bill_of_stones(const Elements& elements, Units units);

// Weight of a diamond round brilliant of this girdle diameter, in carats: the trade's chart from
// 0.75 to 6.5 mm (melee sieves, then single stones; interpolated between its sizes), and beyond it
// in proportion to d^3 from the chart's end, so the weight never jumps. Sources in docs/stones.md.
double round_brilliant_carat(double diameter_mm);

// stones.csv: `shape,diameter_mm,count,carat_each,carat_total`, one row per shape and size, then
// `total,,COUNT,,CARATS`. Carat fields are empty for shapes that are not round brilliants; a stone's
// carats have 4 significant digits, totals 4 decimals.
void write_stones_csv(const std::filesystem::path& path, const BillOfStones& bill);

nlohmann::json to_json(const BillOfStones& bill);

}  // namespace paver
