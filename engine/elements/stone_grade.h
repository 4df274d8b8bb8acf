#pragma once
// Graded stones on the elements (pattern/grade_field.h has the field and the ladder): each
// V-element at the main size takes the ladder's stone for the grade's share at its centre.
#include "elements/elements.h"
#include "map/surface_map.h"
#include "pattern/grade_field.h"

#include <vector>

namespace paver {

// What a graded pass did: the ladder it graded on, how many stones took a smaller size and how
// many of the ladder's sizes were set into the room left between graded stones.
struct GradeReport {
  std::vector<double> ladder;  // surface units, the main stone first; empty when not graded
  int graded = 0;
  int filled = 0;
};

// The others (fill sizes, edge elements) are left; shrinking never makes a collision. Returns how
// many changed.
int grade_stones(const SurfaceMap& map, const GradeField& field, Elements& elements);

}  // namespace paver
