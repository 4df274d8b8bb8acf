#pragma once
// The designer's edits (design.edits) brought to the pattern: added elements become particles of
// their own (no springs: their neighbours make room through the contact rule), and every moved or
// added particle is listed with where it goes. They go there once the design itself is solved
// (solver/edit_relaxation.h), so that an edit changes the pavement around it and nowhere else.
// Deletions act on the final elements: elements/element_deletion.h.
#include "design/element_edits.h"
#include "map/surface_map.h"
#include "pattern/pattern.h"

#include <glm/vec2.hpp>

#include <vector>

namespace paver {

struct EditedParticle {
  int particle = 0;
  glm::dvec2 to{0};
  bool held = true;   // stays at `to`; else relaxes from there
  bool added = false; // the designer's own (edits.added): sits out the design's own solve
};

// Appends the added elements to `pattern` (Pattern::added_points) and lists every edited particle.
// Throws InputError naming the edit when it names a particle the pattern does not have (edits made
// for another spacing, pattern or placement), a uv off `map`, or when two stones it holds in place
// (added, or moved and pinned; `held_diameter` each) would overlap (closer than the diameter plus
// `gap`).
std::vector<EditedParticle> add_edited_points(const SurfaceMap& map, Pattern& pattern, const ElementEdits& edits,
                                              double held_diameter, double gap);

}  // namespace paver
