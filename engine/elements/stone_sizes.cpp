#include "elements/stone_sizes.h"

#include "core/stopwatch.h"
#include "elements/bare_spots.h"
#include "map/lifting.h"

#include <algorithm>
#include <functional>

namespace paver {
namespace {

// A new stone must fit this much wider than itself (relative), so that rounding in its position
// cannot put it on the wrong side of the contact rule; far below anything a jeweller could see.
constexpr double kFitAim = 1e-9;
// Each search fills every spot it finds; the next finds the few that the first's greedy choice
// left between samples. Three have always been enough on the bundled surfaces.
constexpr int kSearchesPerSize = 4;

}  // namespace

int SizeFill::added() const {
  int total = 0;
  for (const Size& s : sizes) total += s.added;
  return total;
}

SizeFill fill_with_smaller_sizes(const SurfaceMap& map, Elements& elements, const ElementsDesign& spec,
                                 double main_stone, const std::atomic<bool>* stop) {
  const Stopwatch watch;
  SizeFill fill;
  std::vector<double> sizes;
  for (const double d : spec.fill_sizes)
    if (d >= kLeastFillShare * main_stone && d < main_stone) sizes.push_back(d);
  std::sort(sizes.begin(), sizes.end(), std::greater<>());
  sizes.erase(std::unique(sizes.begin(), sizes.end()), sizes.end());
  for (const double d : sizes) {
    SizeFill::Size& row = fill.sizes.emplace_back(SizeFill::Size{d, 0});
    SpotBasis basis;
    basis.stone = d;
    basis.spot_stone = d * (1 + kFitAim);
    basis.gap = spec.gap;
    basis.margin = is_atlas(map) ? 0 : spec.margin;
    for (int search = 0; search < kSearchesPerSize; ++search) {
      if (stop && stop->load()) return fill;
      ++fill.rounds;
      const SpotSearch found = find_bare_spots(map, elements, basis, 0, SpotOrder::TightestFirst);
      // Each stone's normal as the map gives every element's; its centre stays the spot's own,
      // where the room was measured.
      std::vector<glm::dvec2> uv;
      for (const BareSpot& spot : found.spots) uv.push_back(spot.uv);
      LiftedPoints lifted;
      lifted.resize(uv.size());
      lift_points(map, uv, lifted);
      for (std::size_t k = 0; k < found.spots.size(); ++k) {
        const BareSpot& spot = found.spots[k];
        // A spot's uv is on its own face, so it lifts; should rounding say otherwise, its face's first corner's.
        const int corner = map.mesh.triangles[std::size_t(spot.triangle)].x;
        const glm::dvec3 normal = lifted.triangle[k] >= 0 ? lifted.normal[k] : map.normals[std::size_t(corner)];
        elements.push_back(ElementKind::Vertex, -1, 0, spot.uv, spot.position, normal, d, spec.vertex.shape);
      }
      row.added += int(found.spots.size());
      if (found.spots.empty()) break;
    }
  }
  fill.milliseconds = watch.milliseconds();
  return fill;
}

}  // namespace paver
