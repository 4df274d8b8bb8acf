#pragma once
// Graded stones (issue 43): pavé whose stones fall off from the main size towards a smaller one,
// as a setter grades them towards a pendant's tip, a ring's edges or where the surface bends
// tightly. The grade is a share of the main stone at every point of the surface:
//   curvature  1 - (1 - r) min(1, kTightCurvatureStones d (H - H0)), H the mean of |H| over the
//              vertices within a main stone (a stone sits on that much of the surface, and a
//              scan's noise averages out), H0 its low percentile (the surface's base curvature):
//              none where the surface is as flat as it gets, the whole grade where it curves as
//              much more as a ball of kTightCurvatureStones stones' radius (a large stone no longer
//              sits on it); not eq. 5's normalised curvature, which spreads a flat scan's noise
//              over the whole range,
//   rim        r at the margin, rising smoothly to 1 over `width` inwards,
//   point      r at the surface's point nearest the design's (a pendant's tip), rising smoothly
//              to 1 over `width` from it, straight-line distance,
// with r = smallest / main. The adaptive pattern follows it (pattern/adaptive_pattern.h): its
// particles are relaxed to the graded spacing and packed to each pair's own contact, so the
// smaller stones lie closer instead of leaving room. Every stone is the step of the size ladder
// nearest the share (stocked sizes: the design's fill sizes between the smallest and the
// main, else 0.05 mm steps, melee's sieve steps); elements/stone_grade.h sizes the elements.
#include "design/design.h"
#include "map/surface_map.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <memory>
#include <vector>

namespace paver {

class BoundaryIndex;
class PointHash;

// Without fill sizes the ladder steps by this much, millimetres.
inline constexpr double kGradeStepMm = 0.05;
// A rim grade's width when the design gives none, in main stones.
inline constexpr double kDefaultGradeWidthStones = 3;
// A particle moving under relaxation or packing takes its grade again once it has moved this many
// spacings: the share is smooth (a rim grade rises over three stones, under 1% over this move),
// and a rim grade's query scans the boundary within the grade's width (taken at every iteration
// and listing it more than doubled the pierced pendant's graded pattern: 4.9 s, now 2.6 s).
inline constexpr double kGradeRefresh = 0.02;
// Mean curvature |H| = 1 / (this many main stones) takes the curvature grade to its smallest
// stone: on a ball of radius 4 d a stone's girdle stands d / 32 off the surface at its edge.
inline constexpr double kTightCurvatureStones = 4;

class GradeField {
public:
  // `main` is the main stone's diameter and `mm_per_unit` the surface unit's size (both > 0); the
  // design's grade must be graded (by != none) with 0 < smallest < main.
  GradeField(const SurfaceMap& map, const ElementsDesign& elements, double main, double mm_per_unit);
  ~GradeField();

  // The share of the main stone wanted at a point of the surface: its position and its (not
  // normalised) curvature. In [least_share(), 1].
  double share(const glm::dvec3& position, double kappa) const;
  double least_share() const { return least_; }
  // The ladder's stone for a share: the size nearest share * main (the larger of two as near).
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
  void smooth_curvature();
  double smoothed_curvature(const glm::dvec3& position, double kappa) const;

  const SurfaceMap& map_;
  GradeBy by_;
  double main_, gap_, least_, margin_, width_;
  std::vector<double> ladder_;
  std::unique_ptr<BoundaryIndex> rims_;
  glm::dvec3 point_{0};  // point: where the share is least
  // Curvature: |H| averaged over a main stone at each vertex, its base, the vertices bucketed.
  std::vector<double> smoothed_;
  double base_ = 0;
  std::unique_ptr<PointHash> vertices_;
};

// The design's grade field on `map` at the design's spacing (> 0); null when it has no grade.
// DesignError naming the key for a grade that cannot apply (grade_problem, design/design.h) or a
// rim grade on a closed surface.
std::shared_ptr<const GradeField> make_grade_field(const SurfaceMap& map, const Design& design);

// The rim grade's refusal on a surface without rims, for a caller that knows it before the map
// (run_pipeline, from the loaded mesh); make_grade_field makes the same check.
void refuse_rim_grade_without_rims(const Design& design, bool has_rims);

// The field's share at each point of `uv` (lifted on the map; 1 where a point lies off it).
std::vector<double> grade_shares(const SurfaceMap& map, const GradeField& field, const std::vector<glm::dvec2>& uv);

}  // namespace paver
