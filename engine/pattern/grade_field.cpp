#include "pattern/grade_field.h"

#include "mesh/triangle_geometry.h"

#include "core/input_error.h"
#include "design/design_keys.h"
#include "core/point_hash.h"
#include "map/boundary_index.h"
#include "map/lifting.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace paver {
namespace {

// Two ladder steps this close (relative) to equally near the wanted size are a tie, which the
// larger takes, whatever rounding did to the product; and the sieve steps stop this close above
// the smallest, which ends the ladder itself.
constexpr double kLadderSlack = 1e-9;
// The curvature grade's base: this percentile of the smoothed curvature (eq. 5's range starts at
// the 5th too).
constexpr double kBasePercentile = 0.05;

std::vector<double> size_ladder(const ElementsDesign& elements, double main, double mm_per_unit) {
  const double smallest = elements.grade.smallest;
  std::vector<double> ladder{main};
  for (const double d : elements.fill_sizes)
    if (d > smallest && d < main) ladder.push_back(d);
  if (ladder.size() == 1) {
    const double step = kGradeStepMm / mm_per_unit;
    for (int k = 1; main - k * step > smallest * (1 + kLadderSlack); ++k) ladder.push_back(main - k * step);
  }
  ladder.push_back(smallest);
  std::sort(ladder.begin(), ladder.end(), std::greater<>());
  ladder.erase(std::unique(ladder.begin(), ladder.end()), ladder.end());
  return ladder;
}

double smooth_step(double t) {
  t = std::clamp(t, 0.0, 1.0);
  return t * t * (3 - 2 * t);
}

// The point of the surface nearest p: a point given a little off the surface (a tip's corner, a
// point picked on a coarser copy) grades from where it touches, down to the smallest stone there.
glm::dvec3 nearest_surface_point(const SurfaceMesh& mesh, const glm::dvec3& p) {
  glm::dvec3 best = p;
  double best_d2 = std::numeric_limits<double>::infinity();
  for (const auto& t : mesh.triangles) {
    const glm::dvec3 q = detail::closest_point_on_triangle(p, mesh.positions[std::size_t(t[0])],
                                                           mesh.positions[std::size_t(t[1])], mesh.positions[std::size_t(t[2])]);
    const double d2 = glm::dot(q - p, q - p);
    if (d2 < best_d2) best_d2 = d2, best = q;
  }
  return best;
}

// From `least` at t = 0 smoothly to exactly 1 (the main size, not a rounding under it) at t >= 1.
double rising_share(double least, double t) { return t >= 1 ? 1.0 : least + (1 - least) * smooth_step(t); }

}  // namespace

GradeField::GradeField(const SurfaceMap& map, const ElementsDesign& elements, double main, double mm_per_unit)
    : map_(map), by_(elements.grade.by), main_(main), gap_(elements.gap), least_(elements.grade.smallest / main),
      margin_(is_atlas(map) ? 0 : elements.margin),
      // Wider than the surface grades it all the same, and keeps the boundary queries local.
      width_(std::min(elements.grade.width > 0 ? elements.grade.width : kDefaultGradeWidthStones * main,
                      bounding_box_diagonal(map.mesh))),
      ladder_(size_ladder(elements, main, mm_per_unit)) {
  if (by_ == GradeBy::Point && elements.grade.point.size() == 3)
    point_ = nearest_surface_point(map.mesh,
                                   glm::dvec3(elements.grade.point[0], elements.grade.point[1], elements.grade.point[2]));
  if (by_ == GradeBy::Rim && !is_atlas(map))
    rims_ = std::make_unique<BoundaryIndex>(map.mesh, margin_ + 0.5 * main + width_);
  if (by_ == GradeBy::Curvature) smooth_curvature();
}

void GradeField::smooth_curvature() {
  const std::vector<glm::dvec3>& positions = map_.mesh.positions;
  if (positions.empty() || map_.curvature.size() != positions.size()) return;
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
  for (const glm::dvec3& p : positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  vertices_ = std::make_unique<PointHash>(positions, CellGrid(lo, hi, main_));
  smoothed_.resize(positions.size());
  for (std::size_t v = 0; v < positions.size(); ++v) {
    double sum = 0;
    int count = 0;
    vertices_->for_each_near(positions[v], [&](int w) {
      if (glm::length(positions[std::size_t(w)] - positions[v]) <= main_) sum += std::abs(map_.curvature[std::size_t(w)]), ++count;
    });
    smoothed_[v] = sum / double(count);  // the vertex itself is always counted
  }
  std::vector<double> sorted = smoothed_;
  const std::size_t at = std::size_t(kBasePercentile * double(sorted.size() - 1));
  std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(at), sorted.end());
  base_ = sorted[at];
}

double GradeField::smoothed_curvature(const glm::dvec3& position, double kappa) const {
  if (!vertices_) return std::abs(kappa);
  double nearest = std::numeric_limits<double>::infinity(), value = std::abs(kappa);
  vertices_->for_each_near(position, [&](int w) {
    const double d = glm::length(map_.mesh.positions[std::size_t(w)] - position);
    if (d < nearest) nearest = d, value = smoothed_[std::size_t(w)];
  });
  return value;  // a vertex farther than a stone away (a coarse mesh): the point's own curvature
}

GradeField::~GradeField() = default;

void refuse_rim_grade_without_rims(const Design& design, bool has_rims) {
  if (design.elements.grade.by == GradeBy::Rim && !has_rims)
    throw DesignError("'" + key_path(Key::grade_by) + "' \"rim\": the surface is closed, so it has no rim to grade "
                      "towards; grade by \"curvature\"");
}

std::shared_ptr<const GradeField> make_grade_field(const SurfaceMap& map, const Design& design) {
  if (design.elements.grade.by == GradeBy::None) return nullptr;
  if (const std::optional<std::string> problem = grade_problem(design)) throw DesignError(*problem);
  const double main = design.elements.vertex.scale * design.pattern.spacing;
  refuse_rim_grade_without_rims(design, !is_atlas(map));
  return std::make_shared<const GradeField>(map, design.elements, main, millimetres_per_unit(design.units));
}

double GradeField::share(const glm::dvec3& position, double kappa) const {
  switch (by_) {
    case GradeBy::Curvature: {
      // Above the surface's own base curvature: a pendant keeps the main size on its body and
      // grades towards the tip.
      const double beyond = std::max(0.0, smoothed_curvature(position, kappa) - base_);
      return 1 - (1 - least_) * std::min(1.0, kTightCurvatureStones * main_ * beyond);
    }
    case GradeBy::Rim: {
      if (!rims_) return 1;
      // The rim row's centres lie half a smallest stone inside the margin: the grade starts there.
      const double in = rims_->nearest(position).distance - margin_ - 0.5 * least_ * main_;
      return rising_share(least_, in / width_);
    }
    case GradeBy::Point:
      // Straight from the point, not along the surface: a tip's stones lie within a few stones of
      // it, where the two differ by the surface's bend only.
      return rising_share(least_, glm::length(position - point_) / width_);
    case GradeBy::None: break;
  }
  return 1;
}

double GradeField::stone_for(double share) const {
  // The nearest step, the larger on a tie: rounding down dropped the whole of a gently curved
  // pendant's body a step for a grade of a few hundredths.
  const double wanted = share * main_;
  double best = ladder_.front();
  for (const double d : ladder_)
    if (std::abs(d - wanted) < std::abs(best - wanted) * (1 - kLadderSlack)) best = d;
  return best;
}

double GradeField::spacing_factor(double share) const {
  const double stone = share * main_;
  return (stone + gap_) / (main_ + gap_);
}

std::vector<double> grade_shares(const SurfaceMap& map, const GradeField& field, const std::vector<glm::dvec2>& uv) {
  LiftedPoints lifted;
  lifted.resize(uv.size());
  lift_points(map, uv, lifted);
  std::vector<double> shares(uv.size(), 1.0);
  for (std::size_t i = 0; i < uv.size(); ++i)
    if (lifted.triangle[i] >= 0) shares[i] = field.share(lifted.position[i], lifted.curvature[i]);
  return shares;
}

}  // namespace paver
