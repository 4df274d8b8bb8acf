#include "elements/stone_sizes.h"

#include "core/stopwatch.h"
#include "elements/bare_spots.h"

#include <glm/geometric.hpp>

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

// The map's vertex normals at a point of face f, blended by its barycentric coordinates in 3D.
glm::dvec3 normal_at(const SurfaceMap& map, int f, const glm::dvec3& p) {
  const glm::ivec3 t = map.mesh.triangles[std::size_t(f)];
  const glm::dvec3 a = map.mesh.positions[std::size_t(t.x)], b = map.mesh.positions[std::size_t(t.y)],
                   c = map.mesh.positions[std::size_t(t.z)];
  const glm::dvec3 n = glm::cross(b - a, c - a);
  const double area = glm::dot(n, n);
  if (!(area > 0)) return glm::normalize(map.normals[std::size_t(t.x)]);
  const double wb = glm::dot(glm::cross(p - a, c - a), n) / area, wc = glm::dot(glm::cross(b - a, p - a), n) / area;
  const glm::dvec3 blended = (1 - wb - wc) * map.normals[std::size_t(t.x)] + wb * map.normals[std::size_t(t.y)] +
                             wc * map.normals[std::size_t(t.z)];
  return glm::length(blended) > 0 ? glm::normalize(blended) : glm::normalize(n);
}

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
      for (const BareSpot& spot : found.spots)
        elements.push_back(ElementKind::Vertex, -1, 0, spot.uv, spot.position, normal_at(map, spot.triangle, spot.position),
                           d, spec.vertex.shape);
      row.added += int(found.spots.size());
      if (found.spots.empty()) break;
    }
  }
  fill.milliseconds = watch.milliseconds();
  return fill;
}

}  // namespace paver
