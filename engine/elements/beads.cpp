#include "elements/beads.h"
#include "design/design_keys.h"

#include "core/number_text.h"
#include "elements/boundary_postprocess.h"
#include "core/point_hash.h"
#include "map/lifting.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace paver {

Elements place_beads(const SurfaceMap& map, const Elements& stones, const ElementsDesign& design) {
  Elements beads;
  if (!design.beads.enabled || stones.size() < 3) return beads;
  const double gap = design.gap;
  double largest = 0;
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < stones.size(); ++i) {
    largest = std::max(largest, stones.diameter[i]);
    lo = glm::min(lo, stones.position[i]);
    hi = glm::max(hi, stones.position[i]);
  }
  const double reach = largest * (1 + kBeadContactSlack) + gap;
  const PointHash hash(stones.position, CellGrid(lo - glm::dvec3(reach), hi + glm::dvec3(reach), reach));
  const auto in_contact = [&](int i, int j) {
    const double limit = 0.5 * (stones.diameter[std::size_t(i)] + stones.diameter[std::size_t(j)]) + gap +
                         kBeadContactSlack * std::min(stones.diameter[std::size_t(i)], stones.diameter[std::size_t(j)]);
    return glm::length(stones.position[std::size_t(i)] - stones.position[std::size_t(j)]) <= limit;
  };
  std::vector<std::vector<int>> neighbours(stones.size());
  for (int i = 0; i < int(stones.size()); ++i)
    hash.for_each_near(stones.position[std::size_t(i)], [&](int j) {
      if (j != i && in_contact(i, j)) neighbours[std::size_t(i)].push_back(j);
    });
  for (auto& list : neighbours) std::sort(list.begin(), list.end());

  // Every triangle of mutual contacts once (i < j < k), its bead under the centres' middle.
  std::vector<std::array<int, 3>> triangles;
  std::vector<glm::dvec2> middles;
  for (int i = 0; i < int(stones.size()); ++i)
    for (const int j : neighbours[std::size_t(i)]) {
      if (j <= i) continue;
      for (const int k : neighbours[std::size_t(j)]) {
        if (k <= j || !std::binary_search(neighbours[std::size_t(i)].begin(), neighbours[std::size_t(i)].end(), k))
          continue;
        triangles.push_back({i, j, k});
        const glm::dvec2 a = stones.uv[std::size_t(i)];  // the other two in one piece with it, across a seam
        middles.push_back((a + nearest_image(map, stones.uv[std::size_t(j)], a) +
                           nearest_image(map, stones.uv[std::size_t(k)], a)) / 3.0);
      }
    }
  LiftedPoints lifted;
  lifted.resize(middles.size());
  lift_points(map, middles, lifted);
  Elements candidates;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    if (lifted.triangle[t] < 0) continue;
    double room = std::numeric_limits<double>::infinity();  // the largest free radius at the bead
    for (const int s : triangles[t])
      room = std::min(room, glm::length(lifted.position[t] - stones.position[std::size_t(s)]) -
                                0.5 * stones.diameter[std::size_t(s)]);
    if (!(room > 0)) continue;
    candidates.push_back(ElementKind::Bead, triangles[t][0], 0, middles[t], lifted.position[t], lifted.normal[t],
                         2 * room * design.beads.scale, ShapeKind::Sphere);
  }
  const double margin = boundary_margin(map, design.margin, design.gap);
  const std::vector<double> to_boundary = distances_to_boundary(map, candidates, margin);
  std::vector<std::uint8_t> outside(candidates.size(), 0);
  for (std::size_t b = 0; b < candidates.size(); ++b)
    outside[b] = !keeps_margin(to_boundary[b], candidates.diameter[b], margin);
  candidates.erase_flagged(outside);
  return candidates;
}

std::optional<std::string> fine_beads_warning(const Elements& beads, Units units) {
  const double mm = millimetres_per_unit(units);
  std::size_t fine = 0;
  double smallest = std::numeric_limits<double>::infinity();
  for (const double d : beads.diameter) {
    smallest = std::min(smallest, d * mm);
    if (d * mm < kFinestCastBeadMm) ++fine;
  }
  if (fine == 0) return std::nullopt;
  return std::to_string(fine) + " of " + std::to_string(beads.size()) + " beads are under " +
         number_text(kFinestCastBeadMm) + " mm (the smallest " + number_text(std::round(smallest * 1000) / 1000) +
         " mm), finer than casting or wax printing holds reliably: raise " + key_path(Key::beads_scale) + " or the gap";
}

}  // namespace paver
