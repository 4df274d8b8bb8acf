#include "report/edge_quality.h"

#include "elements/rim_rows.h"
#include "pattern/design_overlap.h"

#include <nlohmann/json.hpp>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace paver {
namespace {

double upper_percentile(std::vector<double> values, double p) {
  if (values.empty()) return 0;
  const std::size_t k = std::min(values.size() - 1, std::size_t(std::floor(p * double(values.size()))));
  std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(k), values.end());
  return values[k];
}

// Along each rim of `basis.rims`, every `step`: the distance to the nearest girdle less the margin.
std::vector<double> rim_metal(const SurfaceMap& map, const FreeRoom& room, const EdgeBasis& basis, double step) {
  const SpotBasis& spots = basis.spots;
  std::vector<double> metal;
  for (const int l : basis.rims) {
    const std::vector<int>& loop = map.mesh.boundary_loops[std::size_t(l)];
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const glm::dvec3 a = map.mesh.positions[loop[k]], b = map.mesh.positions[loop[(k + 1) % loop.size()]];
      const int n = std::max(1, int(std::ceil(glm::length(b - a) / step)));
      for (int i = 0; i < n; ++i) {
        const glm::dvec3 q = a + (double(i) / n) * (b - a);
        metal.push_back(room.to_elements(q) + spots.gap - spots.margin);
      }
    }
  }
  return metal;
}

}  // namespace

EdgeQuality measure_edges(const SurfaceMap& map, const Elements& elements, const EdgeBasis& basis) {
  EdgeQuality q;
  const SpotBasis& spots = basis.spots;
  if (!(spots.stone > 0) || elements.size() == 0) return q;
  q.measured = true;
  q.pave = basis.pave;
  q.stone = spots.stone;
  q.spot_stone = spots.spot_stone;
  SpotSearch search = find_bare_spots(map, elements, spots);
  q.largest_fit = search.widest;
  q.spots = std::move(search.spots);
  q.bare_spots = long(q.spots.size());
  const FreeRoom room(map, elements, spots, 2 * spots.spot_stone + spots.stone);
  const std::vector<double> metal = rim_metal(map, room, basis, spots.stone / kRimSamplesPerStone);
  q.rim_samples = long(metal.size());
  if (!metal.empty()) {
    q.rim_metal_p95 = upper_percentile(metal, 0.95) / spots.stone;
    q.rim_metal_max = *std::max_element(metal.begin(), metal.end()) / spots.stone;
  }
  return q;
}

double widest_regular_hole(const UnitCell& cell, const ElementsDesign& elements) {
  // The elements of the cells around the origin's, and the origin's cell sampled finely.
  std::vector<glm::dvec2> centres;
  std::vector<double> diameters;
  for (int i = -2; i <= 2; ++i)
    for (int j = -2; j <= 2; ++j) {
      const glm::ivec2 c(i, j);
      if (elements.vertex.enabled)
        for (int v = 0; v < int(cell.vertices.size()); ++v) {
          centres.push_back(cell.position(v, c));
          diameters.push_back(elements.vertex.scale * cell.spacing);
        }
      for (const EdgeElementDesign& spec : elements.edge)
        for (int e = 0; e < int(cell.edges.size()); ++e) {
          const CellEdge& edge = cell.edges[std::size_t(e)];
          if (edge.is_virtual || !spec.sits_on(e)) continue;
          const glm::dvec2 a = cell.position(edge.from, c), b = cell.position(edge.to, c + edge.offset);
          centres.push_back(a + spec.t * (b - a));
          diameters.push_back(spec.scale * cell.spacing);
        }
    }
  constexpr int kSamples = 64;
  double widest = 0;
  for (int i = 0; i < kSamples; ++i)
    for (int j = 0; j < kSamples; ++j) {
      const glm::dvec2 p = (double(i) / kSamples) * cell.a1 + (double(j) / kSamples) * cell.a2;
      double room = std::numeric_limits<double>::infinity();
      for (std::size_t k = 0; k < centres.size(); ++k)
        room = std::min(room, glm::length(p - centres[k]) - 0.5 * diameters[k] - elements.gap);
      widest = std::max(widest, 2 * room);
    }
  return widest;
}

EdgeBasis edge_basis(const SurfaceMap& map, const UnitCell& cell, const ElementsDesign& elements) {
  EdgeBasis basis;
  double largest_edge = 0;
  for (const EdgeElementDesign& spec : elements.edge) largest_edge = std::max(largest_edge, spec.scale);
  SpotBasis& spots = basis.spots;
  spots.stone = (elements.vertex.enabled ? elements.vertex.scale : largest_edge) * cell.spacing;
  if (!(spots.stone > 0) || elements.allow_overlap) return EdgeBasis{};
  const double hole = widest_regular_hole(cell, elements);
  spots.spot_stone = std::max(kSpotStoneShare * spots.stone, kSpotOverHole * hole);
  spots.hole_reach = 0.5 * hole + 0.5 * spots.stone + elements.gap;
  spots.gap = elements.gap;
  spots.margin = is_atlas(map) ? 0 : elements.margin;
  basis.rims = rim_row_loops(map, elements.rim_rows);
  // Pave: a triangle lattice of stones that touch, dense enough that its own holes are narrower
  // than a spot (with edge gems between, the bundled pendants' melee). Other patterns (a honeycomb,
  // whose hexagons' centres are its design; Cairo's pentagons; a grid) are judged by their fill.
  basis.pave = cell.tessellation == Tessellation::Triangle && stones_touch(cell, elements, elements.gap) &&
               kSpotStoneShare * spots.stone >= kSpotOverHole * hole;
  return basis;
}

nlohmann::json to_json(const EdgeQuality& q) {
  if (!q.measured) return nullptr;
  nlohmann::json spots = nlohmann::json::array();
  for (std::size_t i = 0; i < std::min<std::size_t>(q.spots.size(), kSpotsListed); ++i) {
    const BareSpot& s = q.spots[i];
    spots.push_back({{"position", {s.position.x, s.position.y, s.position.z}}, {"uv", {s.uv.x, s.uv.y}},
                     {"fits", s.fits}});
  }
  return {{"stone", q.stone},
          {"pave", q.pave},
          {"spot_stone", q.spot_stone},
          {"bare_spots", q.bare_spots},
          {"largest_stone_that_fits", q.largest_fit},
          {"spots", std::move(spots)},
          {"rim_samples", q.rim_samples},
          {"rim_metal_p95", q.rim_metal_p95},
          {"rim_metal_max", q.rim_metal_max}};
}

}  // namespace paver
