#pragma once
// The quality of a pavement, as numbers: collisions over all pairs, nearest-neighbour spacing,
// spring lengths against their targets, boundary crossings, coverage, and (for curvature-aware
// designs) how spacing follows curvature.
#include "design/guidance.h"
#include "design/design.h"
#include "elements/elements.h"
#include "pattern/grade_field.h"
#include "pattern/interior_depth.h"
#include "pattern/pattern.h"
#include "pattern/unit_cell.h"
#include "map/surface_map.h"
#include "report/edge_quality.h"

#include <nlohmann/json_fwd.hpp>

#include <array>
#include <cstdint>

#include <memory>
#include <vector>

namespace paver {

struct Distribution {
  double min = 0, p5 = 0, median = 0, p95 = 0, max = 0, mean = 0;
  double cv = 0;  // coefficient of variation: standard deviation / mean
};

Distribution distribution_of(std::vector<double> values);

// What the figures are measured against: the design's solver parameters (spring targets), its gap
// and its ideal density.
struct QualityBasis {
  SolverParams solver;
  double gap = 0;                   // elements.gap: the contact rule's required free space
  double margin = 0;                // elements.margin: the free band along the boundary
  double area_per_element = 0;      // the regular pattern's area per element; 0 = fill not measured
  double boundary_strip = 0;        // half an element diameter plus the margin: the strip along the boundary left bare
  double ideal_count = 0;           // ideal_element_count of the surface: what fill is measured against
  double vertex_share = 0;          // V-elements' share of the ideal count (1 per cell vertex)
  double faces_per_cell = 0;        // F-elements of the regular pattern per cell (0 without them)
  double face_share = 0;            // their share of the ideal count
  int regular_valence = 0;          // V-neighbours of a lattice vertex: 6 tri, 4 grid, 3 hex; 0 = no V, or
                                    // the cell's vertices have more than one (Cairo: 3 and 4)
  double spacing = 0;               // D: interior elements lie kInteriorDepth D from the boundary
  std::vector<GuidanceDab> guidance;  // the painted field: the ideal count follows it (design/guidance.h)
  std::shared_ptr<const GradeField> grade;  // graded stones: the ideal count and the spots follow it
  EdgeBasis edges;                  // bare spots and rim metal (report/edge_quality.h)
};


struct PavementQuality {
  long elements = 0, vertex_elements = 0, edge_elements = 0, face_elements = 0;
  long contact_violations = 0;      // pairs closer than r_i + r_j + gap (core/contact_rule.h), all pairs
  double worst_overlap = 0;         // max of 1 - d / (r_i + r_j + gap) over violating pairs
  double min_clearance = 0;         // smallest d - r_i - r_j over all pairs, surface units (negative = overlap)
  double gap = 0;                   // the gap it was measured with
  double margin = 0;                // and the boundary margin (boundary_crossings count footprints inside it)
  double fill = 0;                  // elements / the ideal count (QualityBasis), 0 when not measured
  double vertex_fill = 0, edge_fill = 0, face_fill = 0;  // each kind over its own ideal count; 0 when not placed
  long interior_vertex_elements = 0;  // V-elements kInteriorDepth D or more from the boundary
  double regular_valence_share = 0;   // of those, the share with the lattice's valence (lattice_valence.h)
  Distribution neighbor_ratio;      // nearest-neighbour distance / (r_i + r_j)
  double spring_deviation_median = 0;  // |3D length / L_ab - 1| over pattern (non-virtual) edges
  double spring_deviation_p95 = 0;
  long boundary_crossings = 0;      // elements nearer the surface boundary than their radius
  double coverage = 0;              // sum of element disc areas / surface area
  double spacing_curvature_spearman = 0;  // rank correlation of local spacing and curvature
  bool structure_measured = true;   // false: valence share, spearman and the edges were not measured (Counts)
  EdgeQuality edges;                // bare spots and rim metal (report/edge_quality.h), with Measure::Full
};

// Full: every figure. Counts: all but the lattice valence and the spacing-curvature correlation,
// the two that cost a triangulation or a sort of every element (5 s and 1 s at 1M elements): the
// pipeline's rows before the final one need them for nothing.
enum class Measure { Full, Counts };

// |P_a P_b| / L_ab for every non-virtual pattern edge whose ends are both in use (not retired),
// lifted in double (eq. 5, 6); L_ab graded where the stones are (`grade`: the spacing's share at
// the edge's middle).
std::vector<double> spring_length_ratios(const SurfaceMap& map, const Pattern& pattern,
                                         const std::vector<glm::dvec2>& points, const SolverParams& params,
                                         const std::vector<std::uint8_t>* retired = nullptr,
                                         const GradeField* grade = nullptr);

// Spearman correlation between the local spacing at each V-element (its nearest-neighbour
// distance) and the surface's mean curvature there. 0 when either does not vary.
double spacing_curvature_correlation(const SurfaceMap& map, const Elements& elements);
// The same from the V-elements' map positions and their nearest-neighbour ratios, already measured.
double spacing_curvature_correlation(const SurfaceMap& map, const std::vector<glm::dvec2>& uv,
                                     const std::vector<double>& spacing);

// How many elements the ideal pavement puts on the surface: its area less a strip of
// `basis.boundary_strip` along the boundary, over the area per element (grown by eq. 5's spacing
// factor, squared and averaged over the surface, for curvature-aware designs). 0 without a basis.
double ideal_element_count(const SurfaceMap& map, const QualityBasis& basis);

// The basis of a design whose spacing is resolved, with its unit cell at that spacing, on `map`:
// the cell's area over the elements one cell carries, the V-element's (else the largest) radius,
// and the ideal count they give (computed once here, for every measure of the run).
QualityBasis quality_basis(const SurfaceMap& map, const UnitCell& cell, const ElementsDesign& elements,
                           const SolverParams& solver, const std::vector<GuidanceDab>& guidance = {},
                           std::shared_ptr<const GradeField> grade = nullptr);

PavementQuality measure_pavement(const SurfaceMap& map, const Pattern& pattern,
                                 const std::vector<glm::dvec2>& points, const Elements& elements,
                                 const QualityBasis& basis, const std::vector<std::uint8_t>* retired = nullptr,
                                 Measure depth = Measure::Full);

nlohmann::json to_json(const PavementQuality& q);

// Colour per element on the paper's scale: red (too close) through yellow to green (loose).
std::vector<std::array<std::uint8_t, 3>> neighbor_ratio_colours(const std::vector<double>& ratios);

// The colours of every picture and exported mesh: each element's nearest-neighbour ratio over the
// required distance (radii plus `gap`), so anything not green-ish violates the contact rule.
std::vector<std::array<std::uint8_t, 3>> contact_colours(const Elements& elements, double gap);

}  // namespace paver
