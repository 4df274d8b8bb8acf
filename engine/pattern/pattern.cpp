#include "pattern/pattern.h"
#include "core/number_text.h"

#include "core/input_error.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace paver {
namespace {

double map_area(const SurfaceMap& map) { return surface_area(map.mesh); }

std::string format_number(double v) { return significant_text(v); }

}  // namespace

namespace {

// Points the lattice would put on an area at D = 1: counted from the cell at unit spacing, so that
// a spacing whose square underflows still gets a finite answer (points scale as 1 / D^2).
double point_count_at_unit_spacing(double map_area, const UnitCell& cell, const Placement& placement) {
  const glm::dvec2 u1 = cell.a1 / cell.spacing, u2 = cell.a2 / cell.spacing;
  // The map's area seen in the pattern plane grows with the square of the placement scale.
  const double area = map_area * placement.scale * placement.scale;
  return area / std::abs(u1.x * u2.y - u1.y * u2.x) * double(cell.vertices.size());
}

}  // namespace

double estimate_point_count(const SurfaceMap& map, const UnitCell& cell, const Placement& placement) {
  return point_count_at_unit_spacing(map_area(map), cell, placement) / (cell.spacing * cell.spacing);
}

void refuse_too_many_points(double area, const UnitCell& cell, const Placement& placement, double slack) {
  const double at_unit = point_count_at_unit_spacing(area, cell, placement);
  const double estimate = at_unit / (cell.spacing * cell.spacing);
  if (estimate <= slack * kMaxPatternPoints) return;
  // Rounded up to the three digits printed, so the spacing suggested is itself accepted.
  const double smallest = std::sqrt(at_unit / kMaxPatternPoints);
  const double digit = std::pow(10.0, std::floor(std::log10(smallest)) - 2);
  const double ok_spacing = std::ceil(smallest / digit) * digit;
  throw InputError("spacing D = " + format_number(cell.spacing) + " would create about " + format_number(estimate) +
                   " elements on this surface (area " + format_number(area) + "); the limit is " +
                   format_number(kMaxPatternPoints) + ": use a spacing of at least " + format_number(ok_spacing));
}

void refuse_spacing_larger_than_map(const SurfaceMap& map, double spacing, const Placement& placement) {
  const glm::dvec2 map_extent = map.uv_max - map.uv_min;
  const double map_size = std::max(map_extent.x, map_extent.y) * placement.scale;  // in pattern units
  if (!(spacing < map_size))
    throw InputError("spacing D = " + format_number(spacing) + " is larger than the surface (its map is about " +
                     format_number(map_size) + " across): no two elements fit; use a spacing below " +
                     format_number(map_size));
}

namespace {

// The faces of the lattice (cells c0..c1) whose corners all became points: `point_at(cell,
// vertex, first)` is the point a lattice vertex became, or -1.
void list_faces(const UnitCell& cell, glm::ivec2 c0, glm::ivec2 c1,
                const std::function<int(glm::ivec2, int, bool)>& point_at, Pattern& pattern) {
  const std::vector<CellFace> faces = cell_faces(cell);
  pattern.face_start.assign(1, 0);
  std::vector<int> corners;
  for (int cy = c0.y; cy <= c1.y; ++cy)
    for (int cx = c0.x; cx <= c1.x; ++cx)
      for (const CellFace& face : faces) {
        corners.clear();
        for (const CellFaceCorner& corner : face) {
          const int p = point_at(glm::ivec2(cx, cy) + corner.cell - face[0].cell, corner.vertex, corners.empty());
          if (p < 0) break;
          corners.push_back(p);
        }
        if (corners.size() != face.size()) continue;
        pattern.face_corner.insert(pattern.face_corner.end(), corners.begin(), corners.end());
        pattern.face_start.push_back(int(pattern.face_corner.size()));
      }
}

// An offset (or a scale) that puts the map this many cells from the lattice's origin only
// repeats the lattice, and its cell indices would overflow: refused.
void refuse_far_offset(glm::dvec2 lo, glm::dvec2 hi, const Placement& placement, double map_size) {
  constexpr double kMaxCellIndex = 1e8;
  if (!(std::abs(lo.x) < kMaxCellIndex && std::abs(lo.y) < kMaxCellIndex && std::abs(hi.x) < kMaxCellIndex &&
        std::abs(hi.y) < kMaxCellIndex))
    throw DesignError("placement: the offset (" + format_number(placement.offset.x) + ", " +
                     format_number(placement.offset.y) + ") puts the pattern about " +
                     format_number(std::max({std::abs(lo.x), std::abs(lo.y), std::abs(hi.x), std::abs(hi.y)})) +
                     " cells from the surface's map; the lattice repeats every cell, so use an offset within the "
                     "map's size (about " + format_number(map_size) + ")");
}

// The lattice slots cover the map's bounding box, not its area: a long thin map turned against the
// lattice can need far more of them than it has points. Bounded before allocating.
void refuse_too_many_slots(double slots, double spacing) {
  if (slots > kMaxLatticeSlots)
    throw InputError("the map's bounding box spans " + format_number(slots) + " lattice positions at D = " +
                     format_number(spacing) + " (the surface is long and thin, or turned against the lattice; "
                     "the limit is " + format_number(kMaxLatticeSlots) +
                     "): use a larger spacing, or a placement rotation that lines the lattice up with it");
}

}  // namespace

Pattern build_pattern(const SurfaceMap& map, const UnitCell& cell, const Placement& placement, bool with_faces) {
  refuse_spacing_larger_than_map(map, cell.spacing, placement);
  const glm::dvec2 map_extent = map.uv_max - map.uv_min;
  const double map_size = std::max(map_extent.x, map_extent.y) * placement.scale;  // in pattern units
  refuse_too_many_points(map_area(map), cell, placement);

  // Range of lattice cells that covers the map: express the map's boundary in lattice coordinates.
  const glm::dvec2 a1 = cell.a1, a2 = cell.a2;
  const double det = a1.x * a2.y - a1.y * a2.x;
  auto lattice_coords = [&](glm::dvec2 p) {
    return glm::dvec2((p.x * a2.y - p.y * a2.x) / det, (a1.x * p.y - a1.y * p.x) / det);
  };
  glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  const auto cover = [&](glm::dvec2 q) {
    const glm::dvec2 l = lattice_coords(placement.map_to_pattern(q));
    lo = glm::min(lo, l), hi = glm::max(hi, l);
  };
  // On a map that wraps, the points are those of one period (uv_min..uv_max frame it), and an edge
  // that leaves it goes on from the point one period back.
  const bool wraps = map_wraps(map);
  glm::ivec2 period_cells(0);
  if (wraps) {
    for (const glm::dvec2 q : {map.uv_min, map.uv_max, glm::dvec2(map.uv_min.x, map.uv_max.y),
                               glm::dvec2(map.uv_max.x, map.uv_min.y)})
      cover(q);
    const glm::dvec2 t = lattice_coords(placement.map_to_pattern(glm::dvec2(map.period, 0)) -
                                        placement.map_to_pattern(glm::dvec2(0)));
    period_cells = glm::ivec2(glm::round(t));
    if (!(glm::length(t - glm::dvec2(period_cells)) < 1e-6) || period_cells == glm::ivec2(0))
      throw std::logic_error("build_pattern: the band's period is not a lattice vector (close_band first)");
  } else {
    // Every loop: a hole lies inside its outer loop, but an atlas's charts lie side by side.
    for (const std::vector<int>& loop : map.mesh.boundary_loops)
      for (int v : loop) cover(map.uv[v]);
  }
  const double window_end = map.period_origin + map.period;
  const auto in_window = [&](glm::dvec2 q) { return !wraps || (q.x >= map.period_origin && q.x < window_end); };
  // Periods a point at u lies past the window (-1, 0 or 1): an edge's or face's far end is taken back by it.
  const auto turns_past = [&](double u) { return u >= window_end ? 1 : u < map.period_origin ? -1 : 0; };
  refuse_far_offset(lo, hi, placement, map_size);
  // One extra ring of cells so edges leaving the map are seen from both ends.
  const glm::ivec2 c0 = glm::ivec2(glm::floor(lo)) - 2, c1 = glm::ivec2(glm::ceil(hi)) + 2;
  const int ncx = c1.x - c0.x + 1, ncy = c1.y - c0.y + 1, nv = int(cell.vertices.size());
  refuse_too_many_slots(double(ncx) * double(ncy) * double(nv), cell.spacing);

  Pattern pattern;
  std::vector<int> index(size_t(ncx) * ncy * nv, -1);  // lattice vertex -> point index
  std::vector<glm::dvec2> map_position(index.size());
  auto slot = [&](glm::ivec2 c, int v) -> long {
    if (c.x < c0.x || c.x > c1.x || c.y < c0.y || c.y > c1.y) return -1;
    return (long(c.y - c0.y) * ncx + (c.x - c0.x)) * nv + v;
  };
  for (int cy = c0.y; cy <= c1.y; ++cy)
    for (int cx = c0.x; cx <= c1.x; ++cx)
      for (int v = 0; v < nv; ++v) {
        const glm::ivec2 c(cx, cy);
        const glm::dvec2 q = placement.pattern_to_map(cell.position(v, c));
        map_position[slot(c, v)] = q;
        glm::dvec3 bary;
        if (!in_window(q) || locate_on_map(map, q, bary) < 0) continue;
        index[slot(c, v)] = pattern.point_count();
        pattern.points.push_back(q);
        pattern.point_cell_vertex.push_back(v);
        pattern.point_cell.push_back(c);
      }

  for (int cy = c0.y; cy <= c1.y; ++cy)
    for (int cx = c0.x; cx <= c1.x; ++cx)
      for (int e = 0; e < int(cell.edges.size()); ++e) {
        const CellEdge& edge = cell.edges[e];
        const glm::ivec2 c(cx, cy);
        const long sa = slot(c, edge.from);
        // On a map that wraps, each edge is seen from its `from` end in the period, and its `to`
        // end taken back into the period; `back` is how far it was moved.
        glm::ivec2 to_cell = c + edge.offset;
        glm::dvec2 back(0);
        if (wraps) {
          if (!in_window(map_position[sa])) continue;
          const double to_u = placement.pattern_to_map(cell.position(edge.to, to_cell)).x;
          const int turns = turns_past(to_u);
          to_cell -= turns * period_cells;
          back = glm::dvec2(turns * map.period, 0);
        }
        const long sb = slot(to_cell, edge.to);
        const int a = index[sa], b = sb >= 0 ? index[sb] : -1;
        if (a >= 0 && b >= 0) {
          pattern.edge_a.push_back(a);
          pattern.edge_b.push_back(b);
          pattern.edge_cell_edge.push_back(e);
          pattern.edge_rest_length.push_back(edge.rest_length);
          pattern.edge_virtual.push_back(edge.is_virtual ? 1 : 0);
        } else if ((a >= 0) != (b >= 0) && !edge.is_virtual) {
          const bool from_inside = a >= 0;
          const glm::dvec2 outside = from_inside
              ? placement.pattern_to_map(cell.position(edge.to, c + edge.offset))
              : map_position[sa] - back;
          pattern.crossing_edges.push_back({from_inside ? a : b, outside, e, from_inside});
        }
      }
  if (with_faces) {
    // Each face once, from its first corner's cell; on a map that wraps, from the period, and its
    // other corners taken back into it as the edges' ends are.
    const auto point_at = [&](glm::ivec2 at, int v, bool first) -> int {
      const long s0 = slot(at, v);
      if (s0 < 0 || !wraps) return s0 < 0 ? -1 : index[s0];
      if (first) return in_window(map_position[s0]) ? index[s0] : -1;
      const long s1 = slot(at - turns_past(map_position[s0].x) * period_cells, v);
      return s1 < 0 ? -1 : index[s1];
    };
    list_faces(cell, c0, c1, point_at, pattern);
  }
  if (pattern.point_count() == 0)
    throw InputError("no element of the pattern lands on the surface: spacing D = " + format_number(cell.spacing) +
                     " against a map about " + format_number(map_size) +
                     " across; use a smaller spacing (or a placement that puts the lattice over the map)");
  return pattern;
}

}  // namespace paver
