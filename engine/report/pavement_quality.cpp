#include "report/pavement_quality.h"

#include "core/contact_rule.h"

#include "elements/boundary_postprocess.h"
#include "elements/element_proximity.h"
#include "map/lifting.h"
#include "report/lattice_valence.h"

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

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

// The least finite value, 0 when there is none (as distribution_of's min), without its sort.
double smallest_finite(const std::vector<double>& values) {
  double least = std::numeric_limits<double>::infinity();
  for (double v : values)
    if (std::isfinite(v)) least = std::min(least, v);
  return std::isfinite(least) ? least : 0;
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
                                         const std::vector<std::uint8_t>* retired, const GradeField* grade) {
  const LiftedPoints lifted = lift_all(map, points);
  std::vector<double> ratios;
  for (int e = 0; e < pattern.edge_count(); ++e) {
    if (pattern.edge_virtual[e]) continue;
    const int a = pattern.edge_a[e], b = pattern.edge_b[e];
    if (lifted.triangle[a] < 0 || lifted.triangle[b] < 0) continue;
    if (retired && ((*retired)[a] || (*retired)[b])) continue;
    const double kappa = std::max(lifted.curvature[a], lifted.curvature[b]);
    const double normalised = normalised_curvature(map, kappa);
    const double rest = pattern.edge_rest_length[e];
    double target = (params.c + params.m * normalised) * rest + rest;
    if (grade) {
      const glm::dvec3 middle = 0.5 * (lifted.position[a] + lifted.position[b]);
      target *= grade->spacing_factor(grade->share(middle, 0.5 * (lifted.curvature[a] + lifted.curvature[b])));
    }
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
  return spacing_curvature_correlation(map, vertex_elements.uv, nearest_neighbor_ratios(vertex_elements));
}

double spacing_curvature_correlation(const SurfaceMap& map, const std::vector<glm::dvec2>& uv,
                                     const std::vector<double>& spacing) {
  const LiftedPoints lifted = lift_all(map, uv);
  std::vector<double> s, k;
  for (size_t i = 0; i < spacing.size(); ++i) {
    if (!std::isfinite(spacing[i]) || lifted.triangle[i] < 0) continue;
    s.push_back(spacing[i]);
    k.push_back(lifted.curvature[i]);
  }
  return pearson(ranks(s), ranks(k));
}


// Mean over the surface (vertex weights: a third of each triangle's area) of the squared spacing
// factor of eq. 5, 1 + c + m * normalised |H|: a curvature-aware design asks for that much more
// area per element. 1 for a uniform design.
double mean_area_factor(const SurfaceMap& map, const SolverParams& params, const std::vector<GuidanceDab>& guidance,
                        const GradeField* grade) {
  if (params.c == 0 && params.m == 0 && guidance.empty() && !grade) return 1;
  const SurfaceMesh& mesh = map.mesh;
  std::vector<double> weight(mesh.positions.size(), 0.0);
  for (const glm::ivec3& t : mesh.triangles) {
    const double third = glm::length(glm::cross(mesh.positions[t.y] - mesh.positions[t.x],
                                                mesh.positions[t.z] - mesh.positions[t.x])) / 6;
    weight[t.x] += third, weight[t.y] += third, weight[t.z] += third;
  }
  double sum = 0, total = 0;
  const GuidanceField field(guidance);
  for (size_t v = 0; v < weight.size() && v < map.curvature.size(); ++v) {
    // The painted field scales the spacing on top of the curvature's (solver/guidance_field.h).
    const double painted = guidance.empty() || v >= map.uv.size() ? 1.0 : field.factor(map.uv[v]);
    // Graded stones lie closer where they are smaller (pattern/grade_field.h).
    const double graded =
        grade ? grade->spacing_factor(grade->share(mesh.positions[v], map.curvature[v])) : 1.0;
    const double factor =
        (1 + params.c + params.m * normalised_curvature(map, map.curvature[v])) * painted * graded;
    sum += weight[v] * factor * factor, total += weight[v];
  }
  return total > 0 ? sum / total : 1;
}

double ideal_element_count(const SurfaceMap& map, const QualityBasis& basis) {
  if (!(basis.area_per_element > 0)) return 0;
  // A closed surface has no boundary: its atlas's seams are not forgiven a strip.
  const double area = surface_area(map.mesh) - basis.boundary_strip * (is_atlas(map) ? 0.0 : boundary_length(map.mesh));
  return std::max(area, 0.0) / (basis.area_per_element * mean_area_factor(map, basis.solver, basis.guidance, basis.grade.get()));
}

QualityBasis quality_basis(const SurfaceMap& map, const UnitCell& cell, const ElementsDesign& elements,
                           const SolverParams& solver, const std::vector<GuidanceDab>& guidance,
                           std::shared_ptr<const GradeField> grade) {
  QualityBasis basis;
  basis.solver = solver;
  basis.guidance = guidance;
  basis.grade = grade;
  basis.gap = elements.gap;
  basis.margin = boundary_margin(map, elements.margin, elements.gap);
  double per_cell = 0, largest = 0;
  if (elements.vertex.enabled) per_cell += double(cell.vertices.size());
  for (const EdgeElementDesign& spec : elements.edge) {
    for (int e = 0; e < int(cell.edges.size()); ++e)
      if (!cell.edges[e].is_virtual && spec.sits_on(e))
        ++per_cell;
    largest = std::max(largest, spec.scale * cell.spacing);
  }
  if (elements.face.enabled) {
    basis.faces_per_cell = double(cell_faces(cell).size());
    per_cell += basis.faces_per_cell;
    largest = std::max(largest, elements.face.scale * cell.spacing);
  }
  if (per_cell > 0) basis.area_per_element = std::abs(cell.cell_area()) / per_cell;
  if (elements.vertex.enabled && per_cell > 0) {
    const double vertices = double(cell.vertices.size());
    basis.vertex_share = vertices / per_cell;
    // One valence for every stone only where every cell vertex has it (not a Cairo tiling's 3 and 4).
    std::vector<int> degree(cell.vertices.size(), 0);
    for (const CellEdge& e : cell.edges)
      if (!e.is_virtual) ++degree[std::size_t(e.from)], ++degree[std::size_t(e.to)];
    if (std::all_of(degree.begin(), degree.end(), [&](int d) { return d == degree[0]; }))
      basis.regular_valence = degree[0];
  }
  if (per_cell > 0) basis.face_share = basis.faces_per_cell / per_cell;
  basis.spacing = cell.spacing;
  basis.boundary_strip =
      0.5 * (elements.vertex.enabled ? elements.vertex.scale * cell.spacing : largest) + basis.margin;
  basis.ideal_count = ideal_element_count(map, basis);
  basis.edges = edge_basis(map, cell, elements);
  basis.edges.spots.c = solver.c, basis.edges.spots.m = solver.m, basis.edges.spots.guidance = guidance;
  basis.edges.spots.grade = std::move(grade);
  // A design spaced wider on purpose somewhere (eq. 5 by curvature, a painted field) has stones
  // that do not touch there: room between them is its design, not a bare spot to close. Graded
  // stones are judged by their own fill instead: no place where the ladder's smallest size fits.
  basis.edges.pave = basis.edges.pave && guidance.empty() && !(solver.c > 0) && !basis.edges.spots.grade;
  return basis;
}

PavementQuality measure_pavement(const SurfaceMap& map, const Pattern& pattern,
                                 const std::vector<glm::dvec2>& points, const Elements& elements,
                                 const QualityBasis& basis, const std::vector<std::uint8_t>* retired,
                                 Measure depth) {
  PavementQuality q;
  q.structure_measured = depth == Measure::Full;
  q.elements = long(elements.size());
  q.vertex_elements = std::count(elements.kind.begin(), elements.kind.end(), ElementKind::Vertex);
  q.face_elements = std::count(elements.kind.begin(), elements.kind.end(), ElementKind::Face);
  q.edge_elements = q.elements - q.vertex_elements - q.face_elements;
  q.gap = basis.gap;
  q.margin = basis.margin;
  ProximityFigures proximity = measure_proximity(elements, basis.gap);
  q.contact_violations = proximity.collisions.pairs;
  q.worst_overlap = proximity.collisions.worst_overlap;
  q.min_clearance = smallest_finite(proximity.clearances);
  q.fill = basis.ideal_count > 0 ? double(q.elements) / basis.ideal_count : 0;
  const double ideal_vertices = basis.ideal_count * basis.vertex_share;
  const double ideal_faces = basis.ideal_count * basis.face_share;
  const double ideal_edges = basis.ideal_count - ideal_vertices - ideal_faces;
  q.vertex_fill = ideal_vertices > 0 ? double(q.vertex_elements) / ideal_vertices : 0;
  q.edge_fill = ideal_edges > 0.5 && q.edge_elements > 0 ? double(q.edge_elements) / ideal_edges : 0;
  q.face_fill = ideal_faces > 0 && q.face_elements > 0 ? double(q.face_elements) / ideal_faces : 0;
  q.neighbor_ratio = distribution_of(proximity.neighbor_ratios);
  std::vector<double> deviation = spring_length_ratios(map, pattern, points, basis.solver, retired, basis.grade.get());
  for (double& r : deviation) r = std::abs(r - 1);
  const Distribution dev = distribution_of(deviation);
  q.spring_deviation_median = dev.median;
  q.spring_deviation_p95 = dev.p95;
  const std::vector<double> to_boundary =
      distances_to_boundary(map, elements, kInteriorDepth * basis.spacing + basis.margin);
  double disc_area = 0;
  for (size_t i = 0; i < elements.size(); ++i) {
    // A closed surface's seams are no edge of it: an element may lie across one (refill_seams).
    if (!is_atlas(map) && !keeps_margin(to_boundary[i], elements.diameter[i], basis.margin)) ++q.boundary_crossings;
    disc_area += std::numbers::pi * 0.25 * elements.diameter[i] * elements.diameter[i];
  }
  q.coverage = disc_area / surface_area(map.mesh);
  if (basis.regular_valence > 0 && q.structure_measured) {
    const std::vector<int> valence = lattice_valences(elements, basis.regular_valence, basis.spacing, map.period);
    long regular = 0;
    for (size_t i = 0; i < elements.size(); ++i) {
      if (valence[i] < 0 || to_boundary[i] < kInteriorDepth * basis.spacing) continue;
      ++q.interior_vertex_elements;
      regular += valence[i] == basis.regular_valence;
    }
    q.regular_valence_share = q.interior_vertex_elements > 0 ? double(regular) / q.interior_vertex_elements : 0;
  }
  if (q.structure_measured) q.edges = measure_edges(map, elements, basis.edges);
  // With no edge elements, the ratios above are the vertex elements' own.
  if (q.structure_measured)
    q.spacing_curvature_spearman =
        q.edge_elements == 0 ? spacing_curvature_correlation(map, elements.uv, proximity.neighbor_ratios)
                             : spacing_curvature_correlation(map, elements);
  return q;
}

nlohmann::json to_json(const PavementQuality& q) {
  auto dist = [](const Distribution& d) {
    return nlohmann::json{{"min", d.min}, {"p5", d.p5}, {"median", d.median}, {"p95", d.p95},
                          {"max", d.max}, {"mean", d.mean}, {"cv", d.cv}};
  };
  nlohmann::json json{
      {"elements", q.elements},
      {"vertex_elements", q.vertex_elements},
      {"edge_elements", q.edge_elements},
      {"face_elements", q.face_elements},
      {"contact_violations", q.contact_violations},
      {"worst_overlap", q.worst_overlap},
      {"min_clearance", q.min_clearance},
      {"gap", q.gap},
      {"margin", q.margin},
      {"fill", q.fill},
      {"vertex_fill", q.vertex_fill},
      {"edge_fill", q.edge_fill},
      {"face_fill", q.face_fill},
      {"interior_vertex_elements", q.interior_vertex_elements},
      {"regular_valence_share", q.regular_valence_share},
      {"neighbor_ratio", dist(q.neighbor_ratio)},
      {"spring_deviation_median", q.spring_deviation_median},
      {"spring_deviation_p95", q.spring_deviation_p95},
      {"boundary_crossings", q.boundary_crossings},
      {"coverage", q.coverage},
      {"spacing_curvature_spearman", q.spacing_curvature_spearman},
  };
  if (!q.structure_measured)
    for (const char* key : {"interior_vertex_elements", "regular_valence_share", "spacing_curvature_spearman"})
      json[key] = nullptr;
  // No interior element (a narrow ring): no share, rather than a share of 0 that reads as all defects.
  if (q.interior_vertex_elements == 0) json["regular_valence_share"] = nullptr;
  json["edges"] = to_json(q.edges);
  return json;
}

std::vector<std::array<std::uint8_t, 3>> contact_colours(const Elements& elements, double gap) {
  return neighbor_ratio_colours(nearest_neighbor_ratios(elements, gap));
}

std::vector<std::array<std::uint8_t, 3>> neighbor_ratio_colours(const std::vector<double>& ratios) {
  // Ratios are over the required distance (radii plus gap): red below 0.90, orange to yellow just
  // below 1 (still a violation), dark green at 1 (touching with the gap, the target of a uniform
  // design), light green when loose (1.3 and more).
  struct Stop {
    double ratio;
    double r, g, b;
  };
  static constexpr Stop stops[] = {{0.90, 215, 25, 28},  {0.97, 244, 109, 67}, {0.9999, 254, 224, 139},
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
