#pragma once
// Graded stones (issue 43): pavé whose stones fall off from the main size towards a smaller one,
// as a setter grades them towards a pendant's tip, a ring's edges or where the surface bends
// tightly. The grade is a share of the main stone at every point of the surface:
//   curvature  1 - (1 - r) |H|, with |H| eq. 5's normalised curvature,
//   rim        r at the margin, rising smoothly to 1 over `width` inwards,
// with r = smallest / main. The adaptive pattern follows it (pattern/adaptive_pattern.h): its
// particles are relaxed to the graded spacing and packed to each pair's own contact, so the
// smaller stones lie closer instead of leaving room. Every stone is the largest step of the size
// ladder not above the share (stocked sizes: the design's fill sizes between the smallest and the
// main, else 0.05 mm steps, melee's sieve steps); elements/stone_grade.h sizes the elements.
#include "design/design.h"
#include "map/surface_map.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <memory>
#include <vector>

namespace paver {

class BoundaryIndex;

// Without fill sizes the ladder steps by this much, millimetres.
inline constexpr double kGradeStepMm = 0.05;
// A rim grade's width when the design gives none, in main stones.
inline constexpr double kDefaultGradeWidthStones = 3;

class GradeField {
public:
  // `main` is the main stone's diameter and `mm_per_unit` the surface unit's size (both > 0); the
  // design's grade must be graded (by != none) with 0 < smallest < main.
  GradeField(const SurfaceMap& map, const ElementsDesign& elements, double main, double mm_per_unit);
  ~GradeField();

  // The share of the main stone wanted at a point of the surface: its map point, its position
  // and its (not normalised) curvature. In [least_share(), 1].
  double share(glm::dvec2 uv, const glm::dvec3& position, double kappa) const;
  double least_share() const { return least_; }
  // The ladder's stone for a share: the largest size not above share * main, the smallest when
  // none is.
  double stone_for(double share) const;
  // How much the spacing shrinks where the share is `share`: the stones are share * d apart by
  // their gap, which is not scaled.
  double spacing_factor(double share) const;
  // The same for the stone the ladder gives there: a pair's contact distance is the mean of its
  // two particles' factors times the main stone's.
  double contact_factor(double share) const { return (stone_for(share) + gap_) / (main_ + gap_); }
  const std::vector<double>& ladder() const { return ladder_; }  // main first, largest to smallest
  double main() const { return main_; }

private:
  const SurfaceMap& map_;
  GradeBy by_;
  double main_, gap_, least_, margin_, width_;
  std::vector<double> ladder_;
  std::unique_ptr<BoundaryIndex> rims_;
};

// The design's grade field on `map` at the design's spacing (> 0); null when it has no grade.
// DesignError naming the key for a grade that cannot apply: not a tri pattern of vertex elements
// alone, a smallest stone not under the main one or under a quarter of it (kLeastFillShare), a
// rim grade on a closed surface.
std::shared_ptr<const GradeField> make_grade_field(const SurfaceMap& map, const Design& design);

// The field's share at each point of `uv` (lifted on the map; 1 where a point lies off it).
std::vector<double> grade_shares(const SurfaceMap& map, const GradeField& field, const std::vector<glm::dvec2>& uv);

}  // namespace paver
