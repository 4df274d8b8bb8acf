#pragma once
// The design's words for its pattern (section 4.1): which regular tessellation, and the edge
// operators that change its unit cell (pattern/unit_cell.h applies them).
#include "core/enum_names.h"

#include <glm/vec2.hpp>

#include <vector>

namespace paver {

// The paper's three regular tessellations; two pentagonal ones (its section 7's future work): the
// Cairo tiling (its equilateral member: every edge D, two thirds of the vertices 3-valent, one third
// 4-valent) and the prismatic one (rows of house-shaped pentagons: walls and roofs D, bases 1.2 D); and a cell the
// designer draws (Custom, pattern.cell: CellDesign below).
enum class Tessellation { Triangle, Grid, Hexagon, Cairo, Prismatic, Custom };

// The short names first; the command line's long ones are read too.
PAVER_ENUM_NAMES(Tessellation, {Tessellation::Triangle, "tri"}, {Tessellation::Grid, "grid"},
                 {Tessellation::Hexagon, "hex"}, {Tessellation::Cairo, "cairo"},
                 {Tessellation::Prismatic, "prismatic"}, {Tessellation::Custom, "cell"},
                 {Tessellation::Triangle, "triangle"}, {Tessellation::Grid, "square"},
                 {Tessellation::Hexagon, "hexagon"}, {Tessellation::Custom, "custom"});

// A periodic cell drawn by the designer (tessellation "cell"), in units of D: the lattice vectors,
// the vertices' positions in the cell, and edges named as the operators name them (vertex `from`
// of cell (0,0) to vertex `to` of cell `offset`). pattern/unit_cell.h checks it: planar,
// connected, no crossing or repeated edges.
inline constexpr int kMaxDrawnCellOffset = 3;  // cells an edge of a drawn cell may reach, each way

struct CellVertex {
  glm::dvec2 at{0, 0};
};
struct CellEdgeDesign {
  int from = 0;
  int to = 0;
  glm::ivec2 offset{0, 0};
  bool is_virtual = false;
};
struct CellDesign {
  glm::dvec2 a1{1, 0}, a2{0, 1};
  std::vector<CellVertex> vertices;
  std::vector<CellEdgeDesign> edges;
};

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
