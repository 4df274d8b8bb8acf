#pragma once
// Ring sizes: the finger side of a band as a jeweller orders it. Three systems, each a formula
// of the inside diameter (docs/stones.md, "Ring sizes"):
//   - US and Canada: size s in quarter steps from 0, d = 11.63 mm + 0.8128 mm x s (each size is
//     0.032 in of diameter; US 7 is 17.32 mm).
//   - EU (ISO 8653:2016): the size is the inside circumference in mm, d = s / pi (EU 54 is 17.19 mm).
//   - UK and Australia (BS 6820:1996): letters A to Z with half sizes, A a circumference of 37.5 mm
//     and each half letter 0.625 mm more (UK N 1/2 is 17.31 mm).
#include "core/enum_names.h"

#include <nlohmann/json_fwd.hpp>

#include <string>

namespace paver {

enum class RingSizeSystem { US, EU, UK };
PAVER_ENUM_NAMES(RingSizeSystem, {RingSizeSystem::US, "US"}, {RingSizeSystem::EU, "EU"}, {RingSizeSystem::UK, "UK"});

// The inside diameter in mm of `size` ("7", "7.25"; "54"; "N", "N1/2", "N.5") in `system`.
// Throws InputError naming the size, the system's range and how it is written.
double ring_inside_diameter_mm(RingSizeSystem system, const std::string& size);

// The size of each system nearest to `inside_diameter_mm`, as written ("7", "54.4", "N1/2"), with
// that size's own diameter: {"US": {"size": "7", "inside_diameter_mm": 17.32}, ...}. A diameter
// outside a system's range gets its nearest end.
nlohmann::json nearest_ring_sizes_json(double inside_diameter_mm);

}  // namespace paver
