#include "elements/rim_rows.h"

#include "core/stopwatch.h"
#include "elements/boundary_postprocess.h"
#include "core/contact_rule.h"
#include "core/point_hash.h"
#include "map/boundary_index.h"
#include "map/boundary_walk.h"
#include "map/lifting.h"
#include "map/uv_from_tangent.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace paver {
namespace {

// Samples of the offset curve per diameter: fine enough that placing an element at the nearest
// sample's arc length errs by well under the contact aim's slack.
constexpr double kSamplesPerDiameter = 40;

struct OffsetCurve {
  std::vector<glm::dvec2> uv;
  std::vector<glm::dvec3> position;
  std::vector<double> arc;  // arc length at each sample; the loop closes back to sample 0
  double length = 0;
};

// The curve `offset` inside rim `loop` (3D distance along the surface, through each rim edge's
// triangle), sampled and lifted; samples where an element would break the edge rule (a narrow
// neck, a concave corner: another part of the boundary nearer) are dropped.
OffsetCurve offset_curve(const SurfaceMap& map, const BoundaryWalk& rims, int loop, double offset, double step,
                         const BoundaryIndex& boundary, double diameter, double margin) {
  OffsetCurve curve;
  LiftedPoints lifted;
  lifted.resize(1);
  rims.walk(loop, step, [&](const BoundarySample& at) {
    const UvFromTangent uv_step(map, at.triangle);
    glm::dvec2 uv = at.uv + uv_step(at.into * offset);
    if (lift_points(map, std::span(&uv, 1), lifted) > 0) return;
    // The uv step is linear in the triangle: correct it once so that the lifted point lies at the
    // offset from the rim point (as refill corrects its steps).
    const double got = glm::length(lifted.position[0] - at.position);
    if (got > 0 && std::abs(got - offset) > 1e-3 * offset) {
      uv = at.uv + (uv - at.uv) * (offset / got);
      if (lift_points(map, std::span(&uv, 1), lifted) > 0) return;
    }
    if (!keeps_margin(boundary.nearest(lifted.position[0]).distance, diameter, margin)) return;
    curve.uv.push_back(wrap_point(map, uv));
    curve.position.push_back(lifted.position[0]);
  });
  const std::size_t n = curve.position.size();
  curve.arc.resize(n);
  for (std::size_t i = 1; i < n; ++i) curve.arc[i] = curve.arc[i - 1] + glm::length(curve.position[i] - curve.position[i - 1]);
  if (n > 1) curve.length = curve.arc[n - 1] + glm::length(curve.position[0] - curve.position[n - 1]);
  return curve;
}

// Where an element goes along `curve`: sample `sample` and `t` of the way to the next one.
struct CurvePoint {
  std::size_t sample;
  double t;
  glm::dvec3 position;
};

// The elements' places along `curve`, from sample 0: each `step` (3D chord) beyond the one before,
// between the two samples that straddle it (placing on whole samples lost a fraction of a sample
// per element: a bangle's rim one element); the last ones are dropped until the loop closes with
// `step` between the last and the first. Across a gap in the curve (dropped samples) an element
// goes on the first sample past it.
std::vector<CurvePoint> walk_by_chord(const OffsetCurve& curve, double step) {
  const std::size_t n = curve.position.size();
  std::vector<CurvePoint> chosen;
  if (n == 0) return chosen;
  chosen.push_back({0, 0, curve.position[0]});
  for (std::size_t k = 1; k < n; ++k) {
    const double reach = glm::length(curve.position[k] - chosen.back().position);
    if (reach < step) continue;
    const double before = glm::length(curve.position[k - 1] - chosen.back().position);
    const bool gap = curve.arc[k] - curve.arc[k - 1] > 2 * (curve.length / double(n)) + 1e-12;
    const double t = gap || reach <= before ? 1.0 : std::clamp((step - before) / (reach - before), 0.0, 1.0);
    chosen.push_back({k - 1, t, curve.position[k - 1] * (1 - t) + curve.position[k] * t});
    if (t < 1) --k;  // the next element is measured from this one, which lies before sample k
  }
  while (chosen.size() > 1 && glm::length(chosen.back().position - curve.position[0]) < step) chosen.pop_back();
  return chosen;
}

// Cells of at least `reach` over the surface's box (every element lies on it).
CellGrid surface_grid(const SurfaceMesh& mesh, double reach) {
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (const glm::dvec3& p : mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  return CellGrid(lo - glm::dvec3(reach), hi + glm::dvec3(reach), reach);
}

}  // namespace

bool band_rims_alike(const SurfaceMap& map) {
  if (!is_band(map)) return false;
  const double a = loop_length(map.mesh.positions, map.mesh.boundary_loops[0]);
  const double b = loop_length(map.mesh.positions, map.mesh.boundary_loops[1]);
  return std::max(a, b) <= kAlikeRims * std::min(a, b);
}

RimRows concrete_rim_rows(RimRows rows, bool rows_for_pave) {
  if (rows != RimRows::Auto) return rows;
  return rows_for_pave ? RimRows::All : RimRows::None;
}

std::vector<int> rim_row_loops(const SurfaceMap& map, RimRows rows) {
  std::vector<int> loops;
  if (rows == RimRows::None || rows == RimRows::Auto || is_atlas(map)) return loops;
  if (rows == RimRows::Holes && band_rims_alike(map)) return loops;
  for (int l = rows == RimRows::All ? 0 : 1; l < int(map.mesh.boundary_loops.size()); ++l) loops.push_back(l);
  return loops;
}

RimRowReport place_rim_rows(const SurfaceMap& map, Elements& elements, const ElementsDesign& spec, double spacing) {
  const Stopwatch watch;
  RimRowReport report;
  const std::vector<int> loops = rim_row_loops(map, spec.rim_rows);
  if (loops.empty() || !spec.vertex.enabled || !(spacing > 0)) return report;
  const SurfaceMesh& mesh = map.mesh;
  const double diameter = spec.vertex.scale * spacing;
  const double margin = boundary_margin(map, spec.margin, spec.gap);
  // A hair beyond the margin, so that the edge rule (exact, like the contact rule) holds after rounding.
  const double offset = (0.5 * diameter + margin) * (1 + kContactAim);
  const double neighbours = contact_distance(diameter, diameter, spec.gap) * (1 + kContactAim);
  const BoundaryIndex boundary(mesh, 2 * offset);
  const BoundaryWalk rims(map);

  Elements row;
  LiftedPoints lifted;
  lifted.resize(1);
  for (const int l : loops) {
    const OffsetCurve curve =
        offset_curve(map, rims, l, offset, diameter / kSamplesPerDiameter, boundary, diameter, margin);
    if (curve.position.size() < 3 || !(curve.length > neighbours)) continue;
    // Along the curve by 3D chord: each element at the first sample a step beyond the one before,
    // and the last a step from the first. The step is then widened as far as it keeps the count,
    // so the row closes evenly. Spacing the count evenly by arc length instead let the shortest
    // chord (over a stepped rim's corner) set the spacing of the whole row: a sparse, ragged ring
    // (a pierced pendant's holes, a jeweller's trial).
    const std::vector<CurvePoint> tight = walk_by_chord(curve, neighbours);
    double lo = neighbours, hi = 2 * neighbours;
    for (int halving = 0; halving < 40 && tight.size() > 1; ++halving) {
      const double mid = 0.5 * (lo + hi);
      (walk_by_chord(curve, mid).size() >= tight.size() ? lo : hi) = mid;
    }
    const std::vector<CurvePoint> chosen = tight.size() > 1 ? walk_by_chord(curve, lo) : tight;
    Elements trial;
    for (const CurvePoint& at : chosen) {
      const std::size_t next = (at.sample + 1) % curve.uv.size();
      glm::dvec2 uv = curve.uv[at.sample] * (1 - at.t) + nearest_image(map, curve.uv[next], curve.uv[at.sample]) * at.t;
      uv = wrap_point(map, uv);
      if (lift_points(map, std::span(&uv, 1), lifted) > 0) continue;
      trial.push_back(ElementKind::Vertex, -1, 0, uv, lifted.position[0], lifted.normal[0], diameter, spec.vertex.shape);
    }
    const int placed_here = int(trial.size());
    // Against every row element kept so far, this rim's too (a tight bend folds the offset curve;
    // two holes lie close): one that would touch is left out.
    PointHash placed(row.position, surface_grid(mesh, neighbours));
    int kept = 0;
    for (int i = 0; i < placed_here; ++i) {
      bool clear = keeps_margin(boundary.nearest(trial.position[i]).distance, diameter, margin);
      placed.for_each_near(trial.position[i], [&](int j) {
        if (elements_collide(glm::length(trial.position[i] - row.position[j]), diameter, row.diameter[j], spec.gap))
          clear = false;
      });
      if (!clear) continue;
      row.push_back(ElementKind::Vertex, -1, 0, trial.uv[i], trial.position[i], trial.normal[i], diameter,
                    spec.vertex.shape);
      placed.insert(int(row.size()) - 1);
      ++kept;
    }
    report.placed += kept;
    if (kept > 0) ++report.loops;
  }

  // The pattern's elements that a row element would touch make way.
  if (row.size() > 0) {
    double largest = diameter;
    for (double d : elements.diameter) largest = std::max(largest, d);
    const PointHash hash(elements.position, surface_grid(mesh, 0.5 * (largest + diameter) + spec.gap));
    std::vector<std::uint8_t> remove(elements.size(), 0);
    for (std::size_t i = 0; i < row.size(); ++i)
      hash.for_each_near(row.position[i], [&](int j) {
        if (elements_collide(glm::length(row.position[i] - elements.position[j]), diameter, elements.diameter[j], spec.gap))
          remove[j] = 1;
      });
    report.made_way = int(std::count(remove.begin(), remove.end(), std::uint8_t(1)));
    elements.erase_flagged(remove);
    for (std::size_t i = 0; i < row.size(); ++i)
      elements.push_back(ElementKind::Vertex, -1, 0, row.uv[i], row.position[i], row.normal[i], diameter,
                         spec.vertex.shape);
  }
  report.milliseconds = watch.milliseconds();
  return report;
}

}  // namespace paver
