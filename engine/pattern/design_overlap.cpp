#include "pattern/design_overlap.h"
#include "core/number_text.h"
#include "design/design_keys.h"

#include "core/contact_rule.h"

#include "core/input_error.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

namespace paver {
namespace {

struct LayoutElement {
  glm::dvec2 centre;
  double radius;
  std::string name;
};

// The cell an element belongs to, when it is not the origin cell (a lattice vertex and its
// neighbour are often the same cell vertex, one cell over).
std::string of_cell(glm::ivec2 c) {
  if (c == glm::ivec2(0)) return "";
  return " of the cell at (" + std::to_string(c.x) + ", " + std::to_string(c.y) + ")";
}

std::string format(double v) { return significant_text(v); }

// With a gap: the largest that this layout keeps (elements that touch by design keep none), with
// the check's own `rounding` allowance, rounded down to three digits so that it is one that fits.
std::string largest_gap_text(double gap, double least_clearance, double rounding) {
  if (!(gap > 0)) return "";
  const double fits = least_clearance + rounding;
  if (fits <= 2 * rounding) return "; they touch with no gap at these scales, so none fits";
  const double step = std::pow(10.0, std::floor(std::log10(fits)) - 2);
  return "; the largest gap that fits is " + format(std::floor(fits / step) * step) + " surface units";
}

// The regular pattern's elements in the cells around the origin cell, and which are the origin's.
struct RegularLayout {
  std::vector<LayoutElement> all;
  std::vector<size_t> own;  // indices of the origin cell's elements
  std::vector<char> vertex;  // per element: a V-element
};

RegularLayout regular_layout(const UnitCell& cell, const ElementsDesign& design, double spacing) {
  // Elements of the cells around the origin cell: enough to see every neighbour of its own. An
  // edge reaching k cells away carries elements up to k cells out, whose neighbours lie up to two
  // cells further (a lattice cell is no smaller than an element).
  int range = 2;
  for (const CellEdge& edge : cell.edges)
    if (!edge.is_virtual) range = std::max(range, 2 + std::max(std::abs(edge.offset.x), std::abs(edge.offset.y)));
  RegularLayout layout;
  std::vector<LayoutElement>& all = layout.all;
  std::vector<size_t>& own = layout.own;
  const std::vector<CellFace> faces = design.face.enabled ? cell_faces(cell) : std::vector<CellFace>{};
  for (int cy = -range; cy <= range; ++cy)
    for (int cx = -range; cx <= range; ++cx) {
      const glm::ivec2 c(cx, cy);
      const bool origin = cx == 0 && cy == 0;
      if (design.vertex.enabled)
        for (int v = 0; v < int(cell.vertices.size()); ++v) {
          if (origin) own.push_back(all.size());
          all.push_back({cell.position(v, c), 0.5 * design.vertex.scale * spacing,
                         "the V-element on cell vertex " + std::to_string(v) + of_cell(c)});
          layout.vertex.resize(all.size(), 0);
          layout.vertex.back() = 1;
        }
      for (int s = 0; s < int(design.edge.size()); ++s) {
        const EdgeElementDesign& spec = design.edge[s];
        for (int e = 0; e < int(cell.edges.size()); ++e) {
          const CellEdge& edge = cell.edges[e];
          if (edge.is_virtual) continue;
          if (!spec.sits_on(e)) continue;
          const glm::dvec2 a = cell.position(edge.from, c), b = cell.position(edge.to, c + edge.offset);
          if (origin) own.push_back(all.size());
          all.push_back({a + spec.t * (b - a), 0.5 * spec.scale * spacing,
                         key_path(Key::elements_edge) + "[" + std::to_string(s) + "] on cell edge " + std::to_string(e) +
                             of_cell(c)});
        }
      }
      for (int f = 0; f < int(faces.size()); ++f) {
        if (origin) own.push_back(all.size());
        all.push_back({face_centre(cell, faces[std::size_t(f)], c), 0.5 * design.face.scale * spacing,
                       "the F-element in cell face " + std::to_string(f) + of_cell(c)});
      }
    }
  layout.vertex.resize(all.size(), 0);
  return layout;
}

}  // namespace

void check_design_overlaps(const UnitCell& cell, const ElementsDesign& design, double spacing, double gap) {
  const RegularLayout layout = regular_layout(cell, design, spacing);
  const std::vector<LayoutElement>& all = layout.all;
  // The pair that misses its distance by the most, not the first found: the figures and the
  // largest scale that fits must be those of the nearest neighbours.
  size_t worst_i = 0, worst_j = 0;
  double worst_shortfall = 0;
  double least_clearance = std::numeric_limits<double>::infinity();  // the largest gap that fits
  // The lattice's positions come from cos/sin: elements that touch by design (scale 1 on a
  // triangle lattice) sit at D up to rounding, which must not read as an overlap.
  const double rounding = 1e-9 * spacing;
  for (size_t i : layout.own)
    for (size_t j = 0; j < all.size(); ++j) {
      if (j == i) continue;
      const double d = glm::length(all[i].centre - all[j].centre);
      least_clearance = std::min(least_clearance, clearance_between(d, 2 * all[i].radius, 2 * all[j].radius));
      if (!elements_collide(d + rounding, 2 * all[i].radius, 2 * all[j].radius, gap)) continue;
      const double shortfall = contact_distance(2 * all[i].radius, 2 * all[j].radius, gap) - d;
      if (shortfall > worst_shortfall) worst_shortfall = shortfall, worst_i = i, worst_j = j;
    }
  if (worst_shortfall <= 0) return;
  const LayoutElement& a = all[worst_i];
  const LayoutElement& b = all[worst_j];
  const double d = glm::length(a.centre - b.centre);
  const double need = contact_distance(2 * a.radius, 2 * b.radius, gap);
  throw DesignError(std::string(gap > 0 ? "the design's elements are closer than the gap: "
                                       : "the design's elements overlap: ") +
                    a.name + " and " + b.name + " are " + format(d / spacing) + " D apart but need " +
                    format(need / spacing) + " D" +
                    (gap > 0 ? " (their radii plus the gap, " + format(gap) + " surface units)" : "") +
                    // Two elements of one size: the largest scale that fits, the figure a user asks for.
                    (a.radius == b.radius && d > gap
                         ? "; at this spacing and gap their scale can be at most " + format((d - gap) / spacing) +
                               " (now " + format(2 * a.radius / spacing) + ")"
                         : "") +
                    largest_gap_text(gap, least_clearance, rounding) +
                    "; reduce their scales, move t" + (gap > 0 ? ", reduce the gap or raise the spacing" : "") +
                    " (or set elements.allow_overlap to allow it)");
}

bool stones_touch(const UnitCell& cell, const ElementsDesign& design, double gap) {
  if (!design.vertex.enabled || design.allow_overlap || !(design.vertex.scale > 0)) return false;
  const RegularLayout layout = regular_layout(cell, design, cell.spacing);
  for (size_t i : layout.own) {
    if (!layout.vertex[i]) continue;
    double nearest = std::numeric_limits<double>::infinity();
    for (size_t j = 0; j < layout.all.size(); ++j)
      if (j != i)
        nearest = std::min(nearest, glm::length(layout.all[i].centre - layout.all[j].centre) -
                                        contact_distance(2 * layout.all[i].radius, 2 * layout.all[j].radius, gap));
    if (!(nearest <= kTouchingShare * 2 * layout.all[i].radius)) return false;
  }
  return true;
}

}  // namespace paver
