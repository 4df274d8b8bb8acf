#include "report/pavement_quality.h"

#include "elements/contact_rule.h"

#include "elements/boundary_postprocess.h"
#include "elements/element_proximity.h"
#include "map/lifting.h"

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

namespace paver {
namespace {

double percentile(const std::vector<double>& sorted, double p) {
  if (sorted.empty()) return 0;
  const double pos = p * double(sorted.size() - 1);
  const size_t lo = size_t(std::floor(pos)), hi = std::min(lo + 1, sorted.size() - 1);
  return sorted[lo] + (pos - double(lo)) * (sorted[hi] - sorted[lo]);
}

std::vector<double> ranks(const std::vector<double>& v) {
  std::vector<size_t> order(v.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return v[a] < v[b]; });
  std::vector<double> r(v.size());
  for (size_t i = 0; i < order.size();) {
    size_t j = i;
    while (j + 1 < order.size() && v[order[j + 1]] == v[order[i]]) ++j;
    const double mean_rank = 0.5 * double(i + j);  // ties share their mean rank
    for (size_t k = i; k <= j; ++k) r[order[k]] = mean_rank;
    i = j + 1;
  }
  return r;
}

double pearson(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = double(x.size());
  if (n < 3) return 0;
  const double mx = std::accumulate(x.begin(), x.end(), 0.0) / n, my = std::accumulate(y.begin(), y.end(), 0.0) / n;
  double sxy = 0, sxx = 0, syy = 0;
  for (size_t i = 0; i < x.size(); ++i) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
    syy += (y[i] - my) * (y[i] - my);
  }
  return sxx > 0 && syy > 0 ? sxy / std::sqrt(sxx * syy) : 0;
}

LiftedPoints lift_all(const SurfaceMap& map, const std::vector<glm::dvec2>& points) {
  LiftedPoints lifted;
  lifted.resize(points.size());
  lift_points(map, points, lifted);
  return lifted;
}

}  // namespace

Distribution distribution_of(std::vector<double> values) {
  Distribution d;
  std::erase_if(values, [](double v) { return !std::isfinite(v); });
  if (values.empty()) return d;
  std::sort(values.begin(), values.end());
  d.min = values.front(), d.max = values.back();
  d.p5 = percentile(values, 0.05), d.median = percentile(values, 0.5), d.p95 = percentile(values, 0.95);
  d.mean = std::accumulate(values.begin(), values.end(), 0.0) / double(values.size());
  double var = 0;
  for (double v : values) var += (v - d.mean) * (v - d.mean);
  var /= double(values.size());
  d.cv = d.mean != 0 ? std::sqrt(var) / d.mean : 0;
  return d;
}

std::vector<double> spring_length_ratios(const SurfaceMap& map, const Pattern& pattern,
                                         const std::vector<glm::dvec2>& points, const SolverParams& params,
                                         const std::vector<std::uint8_t>* retired) {
  const LiftedPoints lifted = lift_all(map, points);
  const double range = map.curvature_max - map.curvature_min;
  std::vector<double> ratios;
  for (int e = 0; e < pattern.edge_count(); ++e) {
    if (pattern.edge_virtual[e]) continue;
    const int a = pattern.edge_a[e], b = pattern.edge_b[e];
    if (lifted.triangle[a] < 0 || lifted.triangle[b] < 0) continue;
    if (retired && ((*retired)[a] || (*retired)[b])) continue;
    const double kappa = std::max(lifted.curvature[a], lifted.curvature[b]);
    const double normalised = range > 0 ? std::clamp((kappa - map.curvature_min) / range, 0.0, 1.0) : 0.0;
    const double rest = pattern.edge_rest_length[e];
    const double target = (params.c + params.m * normalised) * rest + rest;
    ratios.push_back(glm::length(lifted.position[b] - lifted.position[a]) / target);
  }
  return ratios;
}

double spacing_curvature_correlation(const SurfaceMap& map, const Elements& elements) {
  Elements vertex_elements;
  for (size_t i = 0; i < elements.size(); ++i)
    if (elements.kind[i] == ElementKind::Vertex)
      vertex_elements.push_back(elements.kind[i], elements.source[i], elements.spec[i], elements.uv[i],
                                elements.position[i], elements.normal[i], elements.diameter[i], elements.shape[i]);
  const std::vector<double> spacing = nearest_neighbor_ratios(vertex_elements);
  const LiftedPoints lifted = lift_all(map, vertex_elements.uv);
  std::vector<double> s, k;
  for (size_t i = 0; i < spacing.size(); ++i) {
    if (!std::isfinite(spacing[i]) || lifted.triangle[i] < 0) continue;
    s.push_back(spacing[i]);
    k.push_back(lifted.curvature[i]);
  }
  return pearson(ranks(s), ranks(k));
}

PavementQuality measure_pavement(const SurfaceMap& map, const Pattern& pattern,
                                 const std::vector<glm::dvec2>& points, const Elements& elements,
                                 const SolverParams& params, const std::vector<std::uint8_t>* retired) {
  PavementQuality q;
  q.elements = long(elements.size());
  q.vertex_elements = std::count(elements.kind.begin(), elements.kind.end(), ElementKind::Vertex);
  q.edge_elements = q.elements - q.vertex_elements;
  const std::vector<Collision> collisions = find_collisions(elements);
  q.collisions = long(collisions.size());
  for (const Collision& c : collisions) q.worst_overlap = std::max(q.worst_overlap, c.overlap);
  q.neighbor_ratio = distribution_of(nearest_neighbor_ratios(elements));
  std::vector<double> deviation = spring_length_ratios(map, pattern, points, params, retired);
  for (double& r : deviation) r = std::abs(r - 1);
  const Distribution dev = distribution_of(deviation);
  q.spring_deviation_median = dev.median;
  q.spring_deviation_p95 = dev.p95;
  const std::vector<double> to_boundary = distances_to_boundary(map, elements);
  double disc_area = 0;
  for (size_t i = 0; i < elements.size(); ++i) {
    if (to_boundary[i] < 0.5 * elements.diameter[i]) ++q.boundary_crossings;
    disc_area += std::numbers::pi * 0.25 * elements.diameter[i] * elements.diameter[i];
  }
  q.coverage = disc_area / surface_area(map.mesh);
  q.spacing_curvature_spearman = spacing_curvature_correlation(map, elements);
  return q;
}

nlohmann::json to_json(const PavementQuality& q) {
  auto dist = [](const Distribution& d) {
    return nlohmann::json{{"min", d.min}, {"p5", d.p5}, {"median", d.median}, {"p95", d.p95},
                          {"max", d.max}, {"mean", d.mean}, {"cv", d.cv}};
  };
  return nlohmann::json{
      {"elements", q.elements},
      {"vertex_elements", q.vertex_elements},
      {"edge_elements", q.edge_elements},
      {"collisions", q.collisions},
      {"worst_overlap", q.worst_overlap},
      {"neighbor_ratio", dist(q.neighbor_ratio)},
      {"spring_deviation_median", q.spring_deviation_median},
      {"spring_deviation_p95", q.spring_deviation_p95},
      {"boundary_crossings", q.boundary_crossings},
      {"coverage", q.coverage},
      {"spacing_curvature_spearman", q.spacing_curvature_spearman},
  };
}

std::vector<std::array<std::uint8_t, 3>> neighbor_ratio_colours(const std::vector<double>& ratios) {
  // Stops: red below 0.90, orange to yellow up to the collision threshold (kContactFactor), dark green at
  // touching (1.0, the target of a uniform design), light green when loose (1.3 and more).
  struct Stop {
    double ratio;
    double r, g, b;
  };
  static constexpr Stop stops[] = {{0.90, 215, 25, 28},  {0.97, 244, 109, 67}, {kContactFactor, 254, 224, 139},
                                   {1.00, 26, 152, 80},  {1.30, 199, 233, 160}};
  std::vector<std::array<std::uint8_t, 3>> colours(ratios.size());
  for (size_t i = 0; i < ratios.size(); ++i) {
    const Stop& last = stops[std::size(stops) - 1];
    const double x = std::isfinite(ratios[i]) ? ratios[i] : last.ratio;
    const Stop* hi = std::find_if(std::begin(stops), std::end(stops), [&](const Stop& s) { return x <= s.ratio; });
    if (hi == std::begin(stops) || hi == std::end(stops)) {
      const Stop& s = hi == std::end(stops) ? last : stops[0];
      colours[i] = {std::uint8_t(s.r), std::uint8_t(s.g), std::uint8_t(s.b)};
      continue;
    }
    const Stop& lo = *(hi - 1);
    const double t = (x - lo.ratio) / (hi->ratio - lo.ratio);
    colours[i] = {std::uint8_t(lo.r + t * (hi->r - lo.r)), std::uint8_t(lo.g + t * (hi->g - lo.g)),
                  std::uint8_t(lo.b + t * (hi->b - lo.b))};
  }
  return colours;
}

}  // namespace paver
