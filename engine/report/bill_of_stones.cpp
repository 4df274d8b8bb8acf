#include "report/bill_of_stones.h"

#include "io/atomic_file.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <utility>

namespace paver {
namespace {

// Weight per stone of round brilliant diamonds, in carats, by girdle diameter (diamondconsultants.in,
// "Sieve Chart"): the middle of each melee sieve's millimetre range (0.70-0.80 mm up to
// 3.60-3.70 mm), then the sizes the same chart lists for single stones (0.20 ct 3.8 mm to 1.00 ct
// 6.5 mm).
constexpr std::array<std::pair<double, double>, 41> kCaratChart = {{
    {0.75, 0.0033}, {0.85, 0.004}, {1.00, 0.005}, {1.125, 0.006}, {1.175, 0.007}, {1.225, 0.008},
    {1.275, 0.009}, {1.325, 0.010}, {1.375, 0.011}, {1.425, 0.012}, {1.475, 0.013}, {1.525, 0.014},
    {1.575, 0.016}, {1.65, 0.018}, {1.75, 0.021}, {1.85, 0.025}, {1.95, 0.029}, {2.05, 0.035},
    {2.15, 0.039}, {2.25, 0.044}, {2.35, 0.052}, {2.45, 0.058}, {2.55, 0.069}, {2.65, 0.074},
    {2.75, 0.078}, {2.85, 0.086}, {2.95, 0.095}, {3.05, 0.108}, {3.15, 0.116}, {3.25, 0.125},
    {3.35, 0.135}, {3.45, 0.146}, {3.55, 0.159}, {3.65, 0.175}, {3.8, 0.20},   {4.1, 0.25},
    {4.5, 0.33},    {4.8, 0.40},  {5.2, 0.50},   {5.8, 0.75},   {6.5, 1.00},
}};

std::string shortest(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", value);
  return text;
}

}  // namespace

// Printing every digit of the float gave rows like 0.436752375.
std::string carat_each_text(double carats) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", carats);
  return text;
}
std::string diameter_mm_text(double diameter_mm) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", diameter_mm);
  std::string s = text;
  if (s.size() > 1 && s.back() == '0' && s.find('.') != std::string::npos) s.pop_back();
  return s;
}

std::string carat_total_text(double carats) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4f", carats);
  return text;
}

bool BillOfStones::weighed() const {
  return std::any_of(rows.begin(), rows.end(), [](const StoneRow& r) { return r.carat_each.has_value(); });
}

double round_brilliant_carat(double d) {
  // Beyond the chart the weight goes with d^3 (the round brilliant rule d^2 x depth x 0.0061 with
  // depth in proportion), scaled to meet the chart at its end: the rule itself is 2.1 times lighter
  // than the chart at 0.75 mm, and a 0.74 mm stone weighed half a 0.75 mm one.
  const auto& [first_d, first_ct] = kCaratChart.front();
  const auto& [last_d, last_ct] = kCaratChart.back();
  if (d < first_d) return first_ct * std::pow(d / first_d, 3);
  if (d > last_d) return last_ct * std::pow(d / last_d, 3);
  const auto upper = std::lower_bound(kCaratChart.begin(), kCaratChart.end(), d,
                                      [](const auto& row, double size) { return row.first < size; });
  if (upper->first == d || upper == kCaratChart.begin()) return upper->second;
  const auto lower = upper - 1;
  const double t = (d - lower->first) / (upper->first - lower->first);
  return lower->second + t * (upper->second - lower->second);
}

BillOfStones bill_of_stones(const Elements& elements, Units units) {
  BillOfStones bill;
  bill.units = units;
  const double mm = millimetres_per_unit(units);
  // Microns as integers: equal sizes group exactly, and a 0.015 mm bead is not billed as 0.02 mm
  // (hundredths did that). Carats come from the stones' own diameters, not the rounded size.
  struct Group {
    long count = 0;
    double carats = 0;
  };
  std::map<std::pair<ShapeKind, long long>, Group> groups;
  for (std::size_t i = 0; i < elements.size(); ++i) {
    const double d_mm = elements.diameter[i] * mm;
    Group& group = groups[{elements.shape[i], std::llround(d_mm * 1000)}];
    ++group.count;
    if (elements.shape[i] == ShapeKind::Gem) group.carats += round_brilliant_carat(d_mm);
  }
  for (const auto& [key, group] : groups) {
    const long count = group.count;
    StoneRow row{key.first, double(key.second) / 1000, count, std::nullopt, 0};
    if (row.shape == ShapeKind::Gem) {
      row.carat_each = group.carats / double(count);
      row.carat_total = group.carats;
    }
    bill.count += count;
    bill.carat_total += row.carat_total;
    bill.rows.push_back(row);
  }
  return bill;
}

void write_stones_csv(const std::filesystem::path& path, const BillOfStones& bill) {
  std::string text = "shape,diameter_mm,count,carat_each,carat_total\n";
  for (const StoneRow& row : bill.rows) {
    text += std::string(enum_name(row.shape)) + "," + shortest(row.diameter_mm) + "," + std::to_string(row.count) + ",";
    if (row.carat_each) text += carat_each_text(*row.carat_each) + "," + carat_total_text(row.carat_total);
    else text += ",";
    text += "\n";
  }
  text += "total,," + std::to_string(bill.count) + ",," + (bill.weighed() ? carat_total_text(bill.carat_total) : "") + "\n";
  write_text_atomically(path, text);
}

nlohmann::json to_json(const BillOfStones& bill) {
  nlohmann::json rows = nlohmann::json::array();
  for (const StoneRow& row : bill.rows) {
    nlohmann::json item = {{"shape", enum_name(row.shape)}, {"diameter_mm", row.diameter_mm}, {"count", row.count}};
    item["carat_each"] = row.carat_each ? nlohmann::json(*row.carat_each) : nlohmann::json(nullptr);
    item["carat_total"] = row.carat_each ? nlohmann::json(row.carat_total) : nlohmann::json(nullptr);  // no "0 ct" for a bead
    rows.push_back(std::move(item));
  }
  return {{"units", enum_name(bill.units)},
          {"rows", std::move(rows)},
          {"count", bill.count},
          {"carat_total", bill.weighed() ? nlohmann::json(bill.carat_total) : nlohmann::json(nullptr)},
          {"carat_rule", "round brilliant diamonds (gem): the trade's chart by diameter from 0.75 to 6.5 mm "
                         "(diamondconsultants.in sieve chart), in proportion to the diameter cubed beyond it"}};
}

}  // namespace paver
