#pragma once
// The trimmed pattern S^ (section 4.2): the unit cell propagated over the plane, placed over the
// map M^ and cut by its boundary. Points and edges are structs of arrays in the map's frame, ready
// to become the solver's particles and springs.
#include "design/placement.h"
#include "pattern/unit_cell.h"
#include "map/surface_map.h"

#include <glm/vec2.hpp>

#include <cstdint>
#include <vector>

namespace paver {

struct Pattern {
  // Points (particles): lattice vertices inside M^.
  std::vector<glm::dvec2> points;          // #P positions in the map's (uv) frame
  std::vector<int> point_cell_vertex;      // #P which unit-cell vertex it instantiates
  std::vector<glm::ivec2> point_cell;      // #P its lattice cell

  // Edges (springs) with both ends inside M^.
  std::vector<int> edge_a, edge_b;         // #E point indices
  std::vector<int> edge_cell_edge;         // #E unit-cell edge index
  std::vector<double> edge_rest_length;    // #E D_ab, the length in the regular design
  std::vector<std::uint8_t> edge_virtual;  // #E 1 for virtual edges (no elements)

  // Lattice edges with exactly one end inside M^: the boundary filling (section 5.4) splits them.
  struct CrossingEdge {
    int inside_point;                      // index into points
    glm::dvec2 outside;                    // the other end, map frame, outside M^
    int cell_edge;                         // unit-cell edge index
    bool inside_is_from;                   // true when the inside end is the edge's `from` end
  };
  std::vector<CrossingEdge> crossing_edges;

  // Faces of the lattice with every corner in M^, each corner a point, counter-clockwise: face f's
  // are face_corner[face_start[f] .. face_start[f + 1]). Only laid out when F-elements ask for
  // them (build_pattern's `with_faces`); an adaptive pattern has none.
  std::vector<int> face_start;
  std::vector<int> face_corner;

  // Point defects of an adaptive pattern (a lattice has none): a particle (tri) or a face (hex:
  // the points around a pentagon or heptagon) whose valence is not the regular lattice's.
  struct Defect {
    int valence;
    std::vector<int> points;
  };
  std::vector<Defect> defects;

  // The last points are the designer's added elements (design.edits.added, in order), with
  // point_cell_vertex -1 and no edges: pattern/pattern_edits.h.
  int added_points = 0;

  int point_count() const { return static_cast<int>(points.size()); }
  int designed_point_count() const { return point_count() - added_points; }
  int edge_count() const { return static_cast<int>(edge_a.size()); }
  int face_count() const { return face_start.empty() ? 0 : static_cast<int>(face_start.size()) - 1; }
};

// Most points a pattern may have; a spacing that would create more is an input error.
inline constexpr double kMaxPatternPoints = 4e6;
// Most lattice positions build_pattern lays out over the map's bounding box (about 20 bytes each).
inline constexpr double kMaxLatticeSlots = 5e7;

// Estimated number of lattice points over the map (area / cell area * vertices per cell).
double estimate_point_count(const SurfaceMap& map, const UnitCell& cell, const Placement& placement);

// Throws InputError, naming the smallest sensible spacing, when `cell` at its spacing would put more
// than `slack` x kMaxPatternPoints points on `area` (the map's; or the surface's, with slack, to
// refuse a spacing before the map is made).
void refuse_too_many_points(double area, const UnitCell& cell, const Placement& placement, double slack = 1);

// Propagates the cell over the map and trims it, and `with_faces` lists the faces whose corners are
// all kept. Throws InputError when the spacing would create more than kMaxPatternPoints points,
// naming the smallest sensible spacing.
Pattern build_pattern(const SurfaceMap& map, const UnitCell& cell, const Placement& placement,
                      bool with_faces = false);

// Throws InputError "spacing D = .. is larger than the surface" when no two elements fit across
// the map; build_pattern checks it, and a band before its closure changes D (a D of 1e9 was said
// to be 7.69 on a ring).
void refuse_spacing_larger_than_map(const SurfaceMap& map, double spacing, const Placement& placement);

}  // namespace paver
