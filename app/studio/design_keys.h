#pragma once
// One design.json key changed by name, as the script's `set KEY VALUE` does: the design goes to
// JSON, the key (a dotted path such as solver.dt, elements.vertex.scale, elements.edge[0].t) is
// set there, and the JSON is read back with design.json's own checks, so every key works and
// every value is checked the way a design file is.
#include "design/design.h"

#include <string>
#include <string_view>

namespace paver::studio {

// "elements.edge[0].t" -> "/elements/edge/0/t". Throws InputError on an empty or malformed key.
std::string design_key_pointer(std::string_view key);

// The design with `key` set to `value`, which is read as JSON (0.25, true, [1, 2], "gem") or,
// when it is not JSON, as a string (gem). Throws InputError naming the key for an unknown key or
// a bad value; `design` is untouched.
Design set_design_key(const Design& design, std::string_view key, std::string_view value);

}  // namespace paver::studio
