#pragma once
// The periodic unit cell of a tessellation (section 4.1): vertices inside one cell of the lattice
// spanned by a1, a2, and edges that may reach into neighbouring cells. Edge operators (flip, add,
// remove) act on the cell, so they propagate to the whole lattice by construction.
#include "design/tessellation.h"

#include <glm/vec2.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace paver {

// Edge from vertex `from` of cell (0,0) to vertex `to` of cell `offset`.
struct CellEdge {
  int from = 0;
  int to = 0;
  glm::ivec2 offset{0, 0};
  double rest_length = 0;   // D_ab: the edge's length in the regular design
  bool is_virtual = false;  // a spring that keeps structure and carries no elements (section 6.1)
};

struct UnitCell {
  Tessellation tessellation = Tessellation::Triangle;
  double spacing = 1;                  // D, the base edge length
  glm::dvec2 a1{1, 0}, a2{0, 1};       // lattice vectors
  std::vector<glm::dvec2> vertices;    // positions of the cell's vertices, relative to the cell origin
  std::vector<CellEdge> edges;

  // Position of vertex v of the cell with lattice index `cell`.
  glm::dvec2 position(int v, glm::ivec2 cell) const {
    return vertices[v] + double(cell.x) * a1 + double(cell.y) * a2;
  }
  // Vector along an edge in the regular design.
  glm::dvec2 edge_vector(const CellEdge& e) const { return position(e.to, e.offset) - vertices[e.from]; }
  double cell_area() const { return a1.x * a2.y - a1.y * a2.x; }
};

// The tessellation with edge length D: Triangle (1 vertex, 3 edges per cell), Grid (1 vertex,
// 2 edges), Hexagon/honeycomb (2 vertices, 3 edges), Cairo (6 vertices, 10 edges: two 4-valent, four
// 3-valent; four pentagons), Prismatic (3 vertices, 5 edges: one 4-valent, two 3-valent; two
// pentagons; its base edges kPrismaticBase D long). Custom has no cell of its own: make_drawn_cell.
UnitCell make_unit_cell(Tessellation tessellation, double spacing);

// The prismatic houses' base over D: wider than their walls and roofs, so that stones on neighbouring
// eaves (joined by no edge) do not touch.
inline constexpr double kPrismaticBase = 1.2;

// The designer's cell (units of D) at spacing D, each vertex taken into the cell a1, a2 span (its
// edges' offsets changed to match, so the same lattice results). Throws InputError naming the vertex or edge when it
// is not a tessellation: lattice vectors not turning counter-clockwise, no vertex, two vertices at
// one place, an edge out of range, of zero length or given twice, two edges crossing or an edge
// through a vertex, a vertex on fewer than two edges, a graph that does not connect the plane.
UnitCell make_drawn_cell(const CellDesign& design, double spacing);

// Most vertices and edges a drawn cell may have (the crossing check compares every pair).
inline constexpr std::size_t kMaxDrawnCellVertices = 64;
inline constexpr std::size_t kMaxDrawnCellEdges = 96;
// How many cells from the origin a drawn vertex may lie (it is taken into the cell).
inline constexpr double kMaxDrawnCellReach = 1e6;

// The smallest angle between two real edges at a vertex of the cell, radians.
double smallest_edge_angle(const UnitCell& cell);

// Applies the operator in place. Throws InputError with a message naming the edge when it cannot
// (no such edge, edge already there, zero-length edge, flip without a face on both sides).
// Flip replaces the edge by the one joining, in each of its two faces, the vertex after it:
// for two triangles this is the classic diagonal flip.
void apply_operator(UnitCell& cell, const EdgeOperator& op);

// One face of the periodic planar graph, as (vertex, cell) corners in counter-clockwise order.
struct CellFaceCorner {
  int vertex;
  glm::ivec2 cell;
};
using CellFace = std::vector<CellFaceCorner>;

// The faces of the periodic graph, one representative per translation class, ignoring virtual
// edges. Empty when the graph has a vertex of degree < 2.
std::vector<CellFace> cell_faces(const UnitCell& cell);

// Where an F-element of `face` sits in the regular design, the face taken `cell` cells over: the
// mean of its corners.
glm::dvec2 face_centre(const UnitCell& cell, const CellFace& face, glm::ivec2 offset = {0, 0});

// Adds virtual edges across every face with more than three sides (both diagonals of a square,
// the three long diagonals of a hexagon, all five of a pentagon) so springs keep the structure from
// shearing or folding.
void add_bracing_edges(UnitCell& cell);

std::string describe_edge(const CellEdge& e);  // "0->1 @ (1,-1)"

}  // namespace paver
