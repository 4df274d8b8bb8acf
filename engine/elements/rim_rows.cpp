#include "elements/rim_rows.h"

#include "core/stopwatch.h"
#include "elements/boundary_postprocess.h"
#include "elements/contact_rule.h"
#include "elements/element_hash.h"
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

// Cells of at least `reach` over the surface's box (every element lies on it).
CellGrid surface_grid(const SurfaceMesh& mesh, double reach) {
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (const glm::dvec3& p : mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  return CellGrid(lo - glm::dvec3(reach), hi + glm::dvec3(reach), reach);
}

}  // namespace

std::vector<int> rim_row_loops(const SurfaceMap& map, RimRows rows) {
  std::vector<int> loops;
  if (rows == RimRows::None || is_atlas(map)) return loops;
  for (int l = rows == RimRows::All ? 0 : 1; l < int(map.mesh.boundary_loops.size()); ++l) loops.push_back(l);
  return loops;
}

RimRowReport place_rim_rows(const SurfaceMap& map, Elements& elements, const Design& design) {
  const Stopwatch watch;
  RimRowReport report;
  const ElementsDesign& spec = design.elements;
  const std::vector<int> loops = rim_row_loops(map, spec.rim_rows);
  if (loops.empty() || !spec.vertex.enabled || !(design.pattern.spacing > 0)) return report;
  const SurfaceMesh& mesh = map.mesh;
  const double diameter = spec.vertex.scale * design.pattern.spacing;
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
    // As many as close the loop evenly (fewer while a chord over a bend comes out short). Where
    // samples were dropped (a neck, a concave step) an element that falls in the gap goes to the
    // gap's nearer end, and does not count against the spacing: a local gap, not a thinner row.
    const double sample_step = diameter / kSamplesPerDiameter;
    for (int count = int(curve.length / neighbours); count >= 1; --count) {
      Elements trial;
      std::vector<std::uint8_t> snapped;  // put on a gap's end: its spacing to the next is not the row's
      std::size_t sample = 0;
      for (int i = 0; i < count; ++i) {
        const double at = curve.length * i / count;
        while (sample + 1 < curve.arc.size() && curve.arc[sample + 1] <= at) ++sample;
        const std::size_t next = (sample + 1) % curve.uv.size();
        const double span = (sample + 1 < curve.arc.size() ? curve.arc[sample + 1] : curve.length) - curve.arc[sample];
        const double w = span > 0 ? std::clamp((at - curve.arc[sample]) / span, 0.0, 1.0) : 0.0;
        glm::dvec2 uv = curve.uv[sample] * (1 - w) + nearest_image(map, curve.uv[next], curve.uv[sample]) * w;
        bool on_gap_end = false;
        if (lift_points(map, std::span(&uv, 1), lifted) > 0 ||
            (span > 2 * sample_step && !keeps_margin(boundary.nearest(lifted.position[0]).distance, diameter, margin))) {
          // In a gap of the curve: on its nearer end (one that lands where another is is left out below).
          uv = w < 0.5 ? curve.uv[sample] : curve.uv[next];
          if (lift_points(map, std::span(&uv, 1), lifted) > 0) continue;
          on_gap_end = true;
        }
        trial.push_back(ElementKind::Vertex, -1, 0, wrap_point(map, uv), lifted.position[0], lifted.normal[0], diameter,
                        spec.vertex.shape);
        snapped.push_back(on_gap_end ? 1 : 0);
      }
      const int placed_here = int(trial.size());
      bool spaced = true;
      for (int i = 0; i < placed_here && spaced && placed_here > 1; ++i) {
        const int j = (i + 1) % placed_here;
        if (snapped[i] || snapped[j]) continue;
        spaced = !elements_collide(glm::length(trial.position[i] - trial.position[j]), diameter, diameter, spec.gap);
      }
      if (!spaced && count > 1) continue;
      // Against every row element kept so far, this rim's too (a tight bend folds the offset curve;
      // two holes lie close): one that would touch is left out.
      ElementHash placed(row, surface_grid(mesh, neighbours));
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
      break;
    }
  }

  // The pattern's elements that a row element would touch make way.
  if (row.size() > 0) {
    double largest = diameter;
    for (double d : elements.diameter) largest = std::max(largest, d);
    const ElementHash hash(elements, surface_grid(mesh, 0.5 * (largest + diameter) + spec.gap));
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
