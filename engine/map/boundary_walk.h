#pragma once
// A walk along a map's boundary loops in steps of equal 3D arc length, for elements placed along
// rims (elements/rim_rows.h) and across a closed surface's seams (refill_seams): at each sample
// the point on the loop, its uv (across a band's seam by nearest image), the triangle on that
// edge, and the unit 3D direction into the triangle, across the edge.
#include "map/surface_map.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <functional>
#include <unordered_map>

namespace paver {

struct BoundarySample {
  glm::dvec3 position;
  glm::dvec2 uv;     // not wrapped into the period
  int triangle = -1;
  glm::dvec3 into;   // unit, tangent to the triangle, across the edge
};

class BoundaryWalk {
public:
  explicit BoundaryWalk(const SurfaceMap& map);  // `map` must outlive the walk

  // Calls visit every `step` (> 0) of loop `loop` of map.mesh, from `step` past its first vertex;
  // degenerate edges are passed over.
  void walk(int loop, double step, const std::function<void(const BoundarySample&)>& visit) const;

private:
  const SurfaceMap& map_;
  std::unordered_map<std::uint64_t, int> triangle_on_;  // boundary edge -> its one triangle
};

}  // namespace paver
