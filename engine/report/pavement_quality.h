#pragma once
// The quality of a pavement, as numbers: collisions over all pairs, nearest-neighbour spacing,
// spring lengths against their targets, boundary crossings, coverage, and (for curvature-aware
// designs) how spacing follows curvature.
#include "design/design.h"
#include "elements/elements.h"
#include "pattern/pattern.h"
#include "map/surface_map.h"

#include <nlohmann/json_fwd.hpp>

#include <array>
#include <cstdint>

#include <vector>

namespace paver {

struct Distribution {
  double min = 0, p5 = 0, median = 0, p95 = 0, max = 0, mean = 0;
  double cv = 0;  // coefficient of variation: standard deviation / mean
};

Distribution distribution_of(std::vector<double> values);

struct PavementQuality {
  long elements = 0, vertex_elements = 0, edge_elements = 0;
  long collisions = 0;              // pairs that collide by the contact rule (elements/contact_rule.h)
  double worst_overlap = 0;         // max of 1 - d / (r_i + r_j) over colliding pairs
  Distribution neighbor_ratio;      // nearest-neighbour distance / (r_i + r_j)
  double spring_deviation_median = 0;  // |3D length / L_ab - 1| over pattern (non-virtual) edges
  double spring_deviation_p95 = 0;
  long boundary_crossings = 0;      // elements nearer the surface boundary than their radius
  double coverage = 0;              // sum of element disc areas / surface area
  double spacing_curvature_spearman = 0;  // rank correlation of local spacing and curvature
};

// |P_a P_b| / L_ab for every non-virtual pattern edge whose ends are both in use (not retired),
// lifted in double (eq. 5, 6).
std::vector<double> spring_length_ratios(const SurfaceMap& map, const Pattern& pattern,
                                         const std::vector<glm::dvec2>& points, const SolverParams& params,
                                         const std::vector<std::uint8_t>* retired = nullptr);

// Spearman correlation between the local spacing at each V-element (its nearest-neighbour
// distance) and the surface's mean curvature there. 0 when either does not vary.
double spacing_curvature_correlation(const SurfaceMap& map, const Elements& elements);

PavementQuality measure_pavement(const SurfaceMap& map, const Pattern& pattern,
                                 const std::vector<glm::dvec2>& points, const Elements& elements,
                                 const SolverParams& params, const std::vector<std::uint8_t>* retired = nullptr);

nlohmann::json to_json(const PavementQuality& q);

// Colour per element on the paper's scale: red (too close) through yellow to green (loose).
std::vector<std::array<std::uint8_t, 3>> neighbor_ratio_colours(const std::vector<double>& ratios);

}  // namespace paver
