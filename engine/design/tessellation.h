#pragma once
// The design's words for its pattern (section 4.1): which regular tessellation, and the edge
// operators that change its unit cell (pattern/unit_cell.h applies them).
#include "core/enum_names.h"

#include <glm/vec2.hpp>

namespace paver {

enum class Tessellation { Triangle, Grid, Hexagon };

// The short names first; the command line's long ones are read too.
PAVER_ENUM_NAMES(Tessellation, {Tessellation::Triangle, "tri"}, {Tessellation::Grid, "grid"},
                 {Tessellation::Hexagon, "hex"}, {Tessellation::Triangle, "triangle"}, {Tessellation::Grid, "square"},
                 {Tessellation::Hexagon, "hexagon"});

// An edge operator. The edge is named by its end vertices and the cell offset of `to`; an edge
// also matches when given reversed (to, from, -offset).
struct EdgeOperator {
  enum class Kind { Flip, Add, Remove };
  Kind kind = Kind::Add;
  int from = 0;
  int to = 0;
  glm::ivec2 offset{0, 0};
  bool is_virtual = false;  // Add only: the new edge is a virtual edge
};

PAVER_ENUM_NAMES(EdgeOperator::Kind, {EdgeOperator::Kind::Flip, "flip"}, {EdgeOperator::Kind::Add, "add"},
                 {EdgeOperator::Kind::Remove, "remove"});

}  // namespace paver
