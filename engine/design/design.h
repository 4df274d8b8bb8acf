#pragma once
// The whole design of a pavement: pattern, operators, elements, placement and the solver
// parameters of section 5. The CLI and the editor share it; design.json is its file form.
#include "design/placement.h"
#include "design/shape_kind.h"
#include "design/tessellation.h"
#include "design/element_edits.h"
#include "design/guidance.h"
#include "design/solver_parameters.h"

#include <algorithm>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace paver {

// How the pattern is laid out: the paper's lattice, or particles grown on the surface with point
// defects where the map distorts it (pattern/adaptive_pattern.h, docs/topology.md), or (auto, the
// default) the lattice unless it measurably tears or leaves bare patches and the adaptive pattern
// does better (pipeline/pavement.h).
enum class Topology { Lattice, Adaptive, Auto };
PAVER_ENUM_NAMES(Topology, {Topology::Lattice, "lattice"}, {Topology::Adaptive, "adaptive"}, {Topology::Auto, "auto"});

// Rows of elements that follow the surface's rims (elements/rim_rows.h): none (the pattern is
// trimmed at the rims, the paper's way), around the holes only, along every rim (the outer edge
// too), or auto (the default): every rim for pave (a triangle lattice of V-stones, issue 40), none
// for every other pattern.
enum class RimRows { None, Holes, All, Auto };
PAVER_ENUM_NAMES(RimRows, {RimRows::None, "none"}, {RimRows::Holes, "holes"}, {RimRows::All, "all"},
                 {RimRows::Auto, "auto"});

// The unit of the surface's coordinates (and so of D, the gap and every length in a design).
// Stone sizes and carats are reported in millimetres from it.
enum class Units { Millimetre, Centimetre, Metre, Inch };
PAVER_ENUM_NAMES(Units, {Units::Millimetre, "mm"}, {Units::Centimetre, "cm"}, {Units::Metre, "m"}, {Units::Inch, "in"});
double millimetres_per_unit(Units u);

// How many cells away an edge operator's `to` may lie, in each direction.
inline constexpr int kMaxOperatorOffset = 3;

struct PatternDesign {
  Tessellation tessellation = Tessellation::Hexagon;
  double spacing = 0;                     // D in surface units; 0 = derive from the surface
  std::vector<EdgeOperator> operators;    // applied in order to the unit cell; offsets within kMaxOperatorOffset
  CellDesign cell;                        // tessellation "cell": the designer's unit cell, units of D
  bool bracing = true;                    // add virtual edges across non-triangular faces
  Topology topology = Topology::Auto;
};

struct VertexElementDesign {
  bool enabled = true;
  double scale = 1;                       // s in (0, 1]: diameter = s * D
  ShapeKind shape = ShapeKind::Sphere;
};

struct EdgeElementDesign {
  double t = 0.5;                         // position along the edge in [0, 1]
  double scale = 0.5;                     // s in (0, 1]: diameter = s * D
  ShapeKind shape = ShapeKind::Sphere;
  std::vector<int> cell_edges;            // unit-cell edge indices it sits on; empty = all

  bool sits_on(int cell_edge) const {
    return cell_edges.empty() || std::find(cell_edges.begin(), cell_edges.end(), cell_edge) != cell_edges.end();
  }
};

// F-elements (the paper's section 7): one at the centre of every face of the pattern, its corners'
// mean, carried by them as the pattern is optimized (elements/element_placement.h).
struct FaceElementDesign {
  bool enabled = false;
  double scale = 0.5;                     // s in (0, 1]: diameter = s * D
  ShapeKind shape = ShapeKind::Sphere;
};

// Beads (shared prongs): a small sphere in the gap between every three stones in contact
// (elements/beads.h). `scale` times the largest sphere that fits there between their footprints.
struct BeadDesign {
  bool enabled = false;
  double scale = 1;                       // in (0, 2]: of the largest that fits between its stones
  double min_diameter = 0.5;              // castable, mm whatever the surface's unit
  double over = 0.05;                     // how far a bead reaches over each girdle it holds, mm
};

// Graded stones (pattern/grade_field.h): the V-elements fall off from the main size towards
// `smallest` where the surface bends most (curvature), near its rims (rim: over `width` from the
// margin inwards) or towards a point such as a pendant's tip (point: over `width` from it), in
// stocked steps.
enum class GradeBy { None, Curvature, Rim, Point };
PAVER_ENUM_NAMES(GradeBy, {GradeBy::None, "none"}, {GradeBy::Curvature, "curvature"}, {GradeBy::Rim, "rim"},
                 {GradeBy::Point, "point"});

struct GradeDesign {
  GradeBy by = GradeBy::None;
  double smallest = 0;                    // the least graded stone, surface units (> 0 when graded)
  double width = 0;                       // rim, point: how far the stones reach the main size; 0 = 3 main stones
  std::vector<double> point;              // point: the stones are smallest at the surface nearest [x, y, z]
};

// Fill sizes (elements.fill_sizes): at most this many, none under this share of the main stone
// (the search for room steps at an eighth of the size, so a tiny one would sweep the surface in
// nanometres).
inline constexpr std::size_t kMaxFillSizes = 32;
inline constexpr double kLeastFillShare = 0.25;

// The most edge elements one design holds (validate_design refuses more).
inline constexpr std::size_t kMaxEdgeElements = 64;

struct ElementsDesign {
  VertexElementDesign vertex;
  std::vector<EdgeElementDesign> edge;
  FaceElementDesign face;
  std::string custom_shape;               // OBJ/OFF/PLY/STL path for ShapeKind::Custom
  bool allow_overlap = false;             // allow elements that intersect by design (paper Fig. 15)
  double gap = 0;                         // required free space between footprints, surface units
  double margin = 0;                      // free band along the boundary: no footprint nearer, surface units
  RimRows rim_rows = RimRows::Auto;       // a row of V-elements along the rims (elements/rim_rows.h)
  bool close_spots = true;                // stones pushed into the bare spots left (elements/bare_spots.h)
  // Stocked sizes smaller than the main stone, surface units: what it leaves is filled with the
  // largest that fits (elements/stone_sizes.h).
  std::vector<double> fill_sizes;
  GradeDesign grade;
  BeadDesign beads;
};

struct Design {
  // design.json's version, written by save_design. Version 1 (before 2026-11-27) differs only in a
  // default: solver.mu_stretched was 0.5 then; version 2 (before 2026-12-02) has no
  // elements.close_spots; version 3 (before 2026-12-03) has no elements.fill_sizes,
  // elements.beads.min_diameter or elements.beads.over; version 4 (until graded stones, 2026-12-02)
  // has no elements.grade; version 5 (until 2026-12-02's pentagonal tessellations) has no pattern.cell
  // or elements.face; version 6 (until 2026-12-03's grade towards a point) has no
  // elements.grade.point; version 7 (until 2026-12-03's edges by default) has no rim_rows auto.
  // All are read, so that an earlier build says which versions it reads rather than that a new key
  // or value is unknown. A file that leaves a key out takes today's default (elements.rim_rows
  // auto and elements.close_spots true since version 8); every saved file writes each key.
  static constexpr int kVersion = 8;
  static constexpr int kOldestVersion = 1;
  Units units = Units::Millimetre;
  PatternDesign pattern;
  ElementsDesign elements;
  Placement placement;
  SolverParams solver;
  ElementEdits edits;                     // single elements pinned, moved, deleted, added
  std::vector<GuidanceDab> guidance;      // painted looser / denser (design/guidance.h)
};

// Paves stones of diameter `stone` (surface units, > 0) with the design's gap between neighbours:
// the vertex elements become round brilliants (gem) of that size and D = stone + gap, so that
// stones on neighbouring lattice vertices are exactly the gap apart (docs/stones.md). A design
// with edge elements keeps its proportions and shapes instead: D = stone / the vertex scale.
void set_stone_size(Design& design, double stone);

// Sets the gap between elements while the vertex elements keep their diameter `stone` (surface
// units; 0 = they have none to keep): as set_stone_size, D = stone + gap, or with edge elements
// the design's proportions (D unchanged). Unlike set_stone_size it keeps the elements' shape.
void set_gap_keeping_stone_size(Design& design, double gap, double stone);

// Whether the design has stones (gem elements), whose diameter a change of D must not touch.
bool keeps_stone_sizes(const ElementsDesign& elements);
// Rescales the gem elements' scales so that their diameters stay what they were at `spacing_before`
// now that D is `spacing_after` (a band's closure).
void keep_stone_sizes(ElementsDesign& elements, double spacing_before, double spacing_after);

// Throws InputError naming the key when a value is out of range.
void validate_design(const Design& design, const std::string& source);

// Why the design's grade cannot apply, naming the key (nullopt when it can or there is none): not
// a tri pattern of vertex elements alone, the lattice, no smallest stone, or (once the spacing is
// known) a smallest not under the main stone or under a quarter of it. validate_design refuses it
// and make_grade_field (pattern/grade_field.h) again at the spacing used.
std::optional<std::string> grade_problem(const Design& design);

// Whether an element that is placed uses ShapeKind::Custom (so elements.custom_shape is needed).
bool uses_custom_shape(const ElementsDesign& elements);

}  // namespace paver
