#include "pattern/grade_field.h"

#include "core/input_error.h"
#include "core/number_text.h"
#include "design/design_keys.h"
#include "map/boundary_index.h"
#include "map/lifting.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace paver {
namespace {

// A ladder's size counts as `wanted` this close above it (relative): the share of a stone that
// is exactly a step must get that step, whatever rounding did to the product.
constexpr double kLadderSlack = 1e-9;

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

}  // namespace

GradeField::GradeField(const SurfaceMap& map, const ElementsDesign& elements, double main, double mm_per_unit)
    : map_(map), by_(elements.grade.by), main_(main), gap_(elements.gap), least_(elements.grade.smallest / main),
      margin_(is_atlas(map) ? 0 : elements.margin),
      width_(elements.grade.width > 0 ? elements.grade.width : kDefaultGradeWidthStones * main),
      ladder_(size_ladder(elements, main, mm_per_unit)) {
  if (by_ == GradeBy::Rim && !is_atlas(map))
    rims_ = std::make_unique<BoundaryIndex>(map.mesh, margin_ + 0.5 * main + width_);
}

GradeField::~GradeField() = default;

std::shared_ptr<const GradeField> make_grade_field(const SurfaceMap& map, const Design& design) {
  const ElementsDesign& e = design.elements;
  const std::string by = key_path(Key::grade_by) + " \"" + std::string(enum_name(e.grade.by)) + "\"";
  if (e.grade.by == GradeBy::None) return nullptr;
  if (design.pattern.tessellation != Tessellation::Triangle)
    throw DesignError(by + ": only a tri pattern's stones are graded yet (its particles are the stones); set " +
                      key_path(Key::pattern_tessellation) + " \"tri\"");
  if (!e.vertex.enabled || !e.edge.empty())
    throw DesignError(by + ": only vertex elements are graded, alone; " +
                      (e.vertex.enabled ? "remove " + key_path(Key::elements_edge) : "enable " + key_path(Key::vertex_enabled)) +
                      " or set " + key_path(Key::grade_by) + " \"none\"");
  const double main = e.vertex.scale * design.pattern.spacing;
  const double smallest = e.grade.smallest;
  const std::string smallest_key = key_and_flag(Key::grade_smallest);
  if (!(smallest > 0))
    throw DesignError(by + " needs the smallest graded stone: set " + smallest_key + " (surface units, under the "
                      "main stone, " + number_text(main) + ")");
  if (!(smallest < main))
    throw DesignError(smallest_key + " " + number_text(smallest) + " is not smaller than the main stone (" +
                      number_text(main) + "): the grade falls off from the main size; give a smaller one");
  if (smallest < kLeastFillShare * main)
    throw DesignError(smallest_key + " " + number_text(smallest) + " is less than a quarter of the main stone (" +
                      number_text(main) + "), too small to set beside it: give a larger one");
  if (e.grade.by == GradeBy::Rim && is_atlas(map))
    throw DesignError(by + ": the surface is closed, so it has no rim to grade towards; grade by \"curvature\"");
  return std::make_shared<const GradeField>(map, e, main, millimetres_per_unit(design.units));
}

double GradeField::share(glm::dvec2, const glm::dvec3& position, double kappa) const {
  switch (by_) {
    case GradeBy::Curvature: return 1 - (1 - least_) * normalised_curvature(map_, kappa);
    case GradeBy::Rim: {
      if (!rims_) return 1;
      // The rim row's centres lie half a smallest stone inside the margin: the grade starts there.
      const double in = rims_->nearest(position).distance - margin_ - 0.5 * least_ * main_;
      return least_ + (1 - least_) * smooth_step(in / width_);
    }
    case GradeBy::None: break;
  }
  return 1;
}

double GradeField::stone_for(double share) const {
  const double wanted = share * main_ * (1 + kLadderSlack);
  for (const double d : ladder_)
    if (d <= wanted) return d;
  return ladder_.back();
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
    if (lifted.triangle[i] >= 0) shares[i] = field.share(uv[i], lifted.position[i], lifted.curvature[i]);
  return shares;
}

}  // namespace paver
