#pragma once
// Elements on the pattern (section 4.1): a V-element on every point, the design's E-elements on
// every non-virtual edge at their t, and an F-element in every face the pattern lists (section 7's
// future work), lifted to the surface (eq. 2) with their normals.
#include "design/design.h"
#include "elements/elements.h"
#include "pattern/pattern.h"
#include "map/surface_map.h"

#include <cstdint>
#include <vector>

namespace paver {

// Where an E-element at t along edge (a, b) sits:
// - MapLine: at a + t (b - a) in the map, lifted (the paper's eq. 2);
// - SurfaceChord: on the surface nearest A + t (B - A) between the lifted ends. The adaptive
//   pattern uses it: its edges cross maps sheared so much that the map's midpoint of an edge
//   can lift next to one of its ends.
enum class EdgeAnchor { MapLine, SurfaceChord };
inline EdgeAnchor edge_anchor(Topology topology) {
  return topology == Topology::Adaptive ? EdgeAnchor::SurfaceChord : EdgeAnchor::MapLine;
}

// `points` are the particle positions to use (the pattern's, or the optimizer's result);
// `retired` (optional, #P) marks particles the optimizer retired: they carry no V-element.
Elements place_elements(const SurfaceMap& map, const Pattern& pattern,
                        const std::vector<glm::dvec2>& points, const ElementsDesign& design,
                        double spacing, const std::vector<std::uint8_t>* retired = nullptr,
                        EdgeAnchor anchor = EdgeAnchor::MapLine);

}  // namespace paver
