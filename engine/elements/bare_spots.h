#pragma once
// Bare spots (issue 40): places of the surface, inside the margin, where another stone would keep
// the gap to every element, and closing them. A jeweller sees a spot where a stone of 0.8 d fits
// as a hole in the pavé, whatever the fill says.
#include "core/point_hash.h"
#include "design/design.h"
#include "design/guidance.h"
#include "elements/elements.h"
#include "pattern/grade_field.h"
#include "map/surface_map.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <atomic>
#include <memory>
#include <vector>

namespace paver {

// Where spots are looked for, the surface's triangles split until each piece is this many times
// smaller than d or holds no spot for certain (the room around a point changes by no more than the
// point moves).
inline constexpr int kSpotSamplesPerStone = 8;
// A spot fits a stone of 0.8 d, or 1.25 times the widest stone that fits in the design's own
// regular pattern (the centre of a honeycomb's hexagon), whichever is wider.
inline constexpr double kSpotStoneShare = 0.8;
inline constexpr double kSpotOverHole = 1.25;
// The closing packs each spot's zone on its own, some 30-55 ms a zone on this 2-core machine (the
// 10k-point lily: 89 stones pushed in, 4.9 s; 1M would take many minutes): a pavement of more
// stones than this keeps its spots, and the run says so.
inline constexpr std::size_t kMostStonesClosed = 50'000;

struct SpotBasis {
  double stone = 0;       // d, surface units
  double spot_stone = 0;  // a spot fits a stone this wide, where the design's spacing is its own
  double hole_reach = 0;  // the regular pattern's widest hole: from its centre to the nearest element's
  double gap = 0;         // elements.gap
  double margin = 0;      // elements.margin; 0 on a closed surface, whose seams are no rims
  // Where the design spaces its elements wider (eq. 5's c and m by curvature, a painted guidance
  // field), its holes grow with the spacing, and so does the stone a spot must fit.
  double c = 0, m = 0;
  std::vector<GuidanceDab> guidance;
  // Graded stones (pattern/grade_field.h): the spot stone shrinks with the grade's share.
  std::shared_ptr<const GradeField> grade;

  // The stone a spot must fit at a point of face `f` with barycentric (u, v) and map point uv.
  double spot_stone_at(const SurfaceMap& map, int f, glm::dvec2 w, glm::dvec2 uv) const;
  // The narrowest spot stone anywhere: spots narrower than it are none for certain.
  double narrowest_spot_stone() const;
};

class BoundaryIndex;

// The free room around points of the surface: how far a point is from every element's footprint
// (less the gap) and from the rims (less the margin), capped at `reach`. The elements must outlive
// it, unmoved.
class FreeRoom {
public:
  FreeRoom(const SurfaceMap& map, const Elements& elements, const SpotBasis& basis, double reach);
  ~FreeRoom();
  double to_elements(const glm::dvec3& p) const;
  double to_rims(const glm::dvec3& p) const;  // `reach` on a closed surface
  // The widest stone whose footprint keeps the gap and the margin, centred at p.
  double fits(const glm::dvec3& p) const { return 2 * std::min(to_elements(p), to_rims(p)); }

private:
  static CellGrid grid(const SurfaceMap& map, const Elements& elements, double reach);
  const Elements& elements_;
  double gap_, margin_, reach_;
  std::unique_ptr<BoundaryIndex> rims_;
  PointHash hash_;
};

struct BareSpot {
  glm::dvec3 position{0};
  glm::dvec2 uv{0};
  int triangle = -1;  // of the map's mesh
  double fits = 0;    // the widest stone that fits there, keeping the gap and the margin
  double wanted = 0;  // the stone a spot there must fit (SpotBasis::spot_stone_at, less the slack)
};

struct SpotSearch {
  std::vector<BareSpot> spots;  // each a stone of `wanted` that keeps the gap to those before it, widest first
  double widest = 0;            // the widest stone that fits anywhere (capped at a few d: "at least")
};

// Which spots are taken first where they exclude each other: the widest (a hole's middle: the
// verdict's), or the tightest (a stone against its neighbours: the densest filling).
enum class SpotOrder { WidestFirst, TightestFirst };

// Inputs: the map the elements' uv are on, the elements, the basis, and how much narrower than the
// basis's spot stone a spot may be (0 for the spots the verdict counts). Output: the spots, found
// on the surface in 3D over all elements.
SpotSearch find_bare_spots(const SurfaceMap& map, const Elements& elements, const SpotBasis& basis,
                           double slack = 0, SpotOrder order = SpotOrder::WidestFirst);

struct SpotClosing {
  int added = 0;       // stones of the design's size put into spots
  int pushed = 0;      // of them, into spots their neighbours were moved to widen
  int shared = 0;      // zones spread out to share a spot's room, where no stone could be pushed in
  int of_edge_size = 0;  // of them, stones of the design's E-element size, where no V-stone could go
  bool too_many_stones = false;  // more than kMostStonesClosed: the spots were left as they were
  int rounds = 0;
  double milliseconds = 0;
};

// Puts a V-element of the design's size into every spot where one fits, and where a spot fits a
// smaller stone only, moves the stones around it (within two diameters, the rest held) by contact
// packing on the surface to make room; a patch that cannot be packed is left as it was. Inputs:
// the map the elements' uv are on, the elements (same-size V-elements only are moved), the design's
// elements at spacing D, the basis, and per element whether it holds where it is (a designer's
// moved or added stone; none when null). The added elements have source -1, as the refill's.
SpotClosing close_bare_spots(const SurfaceMap& map, Elements& elements, const ElementsDesign& spec, double spacing,
                             const SpotBasis& basis, const std::atomic<bool>* stop = nullptr,
                             const std::vector<char>* held = nullptr);

}  // namespace paver
