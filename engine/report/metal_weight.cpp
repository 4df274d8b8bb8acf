#include "report/metal_weight.h"

#include <nlohmann/json.hpp>

namespace paver {

const std::vector<Alloy>& jewellery_alloys() {
  static const std::vector<Alloy> alloys = {
      {"24k gold (999)", 19.32},         {"18k yellow gold (750)", 15.5}, {"14k yellow gold (585)", 13.1},
      {"sterling silver (925)", 10.36}, {"platinum 950", 20.1},          {"palladium 950", 12.0},
  };
  return alloys;
}

double metal_grams(double volume, Units units, const Alloy& alloy) {
  const double mm = millimetres_per_unit(units);
  const double cubic_cm = volume * mm * mm * mm / 1000.0;
  return cubic_cm * alloy.density_g_cm3;
}

nlohmann::json metal_weights_json(double volume, Units units) {
  nlohmann::json rows = nlohmann::json::array();
  for (const Alloy& a : jewellery_alloys())
    rows.push_back({{"alloy", a.name}, {"density_g_cm3", a.density_g_cm3}, {"grams", metal_grams(volume, units, a)}});
  return rows;
}

}  // namespace paver
