#pragma once
// The metal's weight from its volume: what a caster charges by and a jeweller quotes. Densities
// are typical values for common jewellery alloys (docs/stones.md gives their ranges and why an
// alloy maker's figure is the one to trust for a quote).
#include "design/design.h"

#include <nlohmann/json_fwd.hpp>

#include <string_view>
#include <vector>

namespace paver {

struct Alloy {
  std::string_view name;     // "18k yellow gold (750)"
  double density_g_cm3;
};

// 24k gold, 18k and 14k yellow gold, sterling silver, platinum 950, palladium 950.
const std::vector<Alloy>& jewellery_alloys();

// `volume` in cubic surface units of `units`; grams.
double metal_grams(double volume, Units units, const Alloy& alloy);

// [{"alloy": ..., "density_g_cm3": ..., "grams": ...}, ...] for every alloy above.
nlohmann::json metal_weights_json(double volume, Units units);

}  // namespace paver
