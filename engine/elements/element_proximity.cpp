#include "elements/element_proximity.h"

#include "core/point_hash.h"
#include "core/contact_rule.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

namespace paver {
namespace {

// The elements' bounding box.
struct Box {
  glm::dvec3 lo{0.0}, hi{0.0};
  double largest_side() const { return std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z}); }
};

Box bounding_box(const Elements& e) {
  if (e.size() == 0) return {};
  Box box{e.position[0], e.position[0]};
  for (const glm::dvec3& p : e.position) box.lo = glm::min(box.lo, p), box.hi = glm::max(box.hi, p);
  return box;
}

// Cells at least `cell` wide over the elements' box (callers pass one largest diameter plus the
// gap, so any violating pair lies in the same or adjacent cells); CellGrid may widen them.
PointHash hash_over(const Elements& e, const Box& box, double cell) { return PointHash(e.position, CellGrid(box.lo, box.hi, cell)); }

double largest_diameter(const Elements& e) {
  double d = 0;
  for (double x : e.diameter) d = std::max(d, x);
  return d > 0 ? d : 1;
}

}  // namespace

namespace {

// The proximity searches split the elements into chunks of consecutive indices searched in
// parallel, each chunk's results kept apart and joined in chunk order: the same result on any
// number of threads.
constexpr int kChunk = 4096;

int chunk_count(int n) { return (n + kChunk - 1) / kChunk; }

// Calls f(chunk, begin, end) for every chunk [begin, end) of [0, n), in parallel.
template <class F>
void for_each_chunk(int n, F&& f) {
  tbb::parallel_for(0, chunk_count(n), [&](int chunk) { f(chunk, chunk * kChunk, std::min(n, (chunk + 1) * kChunk)); });
}

// The chunks' results, one after the other in chunk order.
template <class T>
std::vector<T> joined(const std::vector<std::vector<T>>& parts) {
  std::size_t total = 0;
  for (const auto& part : parts) total += part.size();
  std::vector<T> out;
  out.reserve(total);
  for (const auto& part : parts) out.insert(out.end(), part.begin(), part.end());
  return out;
}

// Elements i and j, `d` apart, as a collision, if they collide by the rule with `gap`.
std::optional<Collision> collision_of(const Elements& elements, int i, int j, double d, double gap) {
  const double di = elements.diameter[i], dj = elements.diameter[j];
  if (!elements_collide(d, di, dj, gap)) return std::nullopt;
  return Collision{i, j, d, 1 - d / contact_distance(di, dj, gap), clearance_between(d, di, dj)};
}

void add_to(CollisionTally& tally, const Collision& c) {
  ++tally.pairs;
  tally.worst_overlap = std::max(tally.worst_overlap, c.overlap);
}

CollisionTally total_of(const std::vector<CollisionTally>& tallies) {
  CollisionTally total;
  for (const CollisionTally& t : tallies)
    total.pairs += t.pairs, total.worst_overlap = std::max(total.worst_overlap, t.worst_overlap);
  return total;
}

// Calls found(collision) for every colliding pair (i < j) with i in [begin, end), in no particular order.
template <class Found>
void collisions_from(const PointHash& hash, const Elements& elements, double gap, int begin, int end, Found&& found) {
  for (int i = begin; i < end; ++i) {
    hash.for_each_near(elements.position[i], [&](int j) {
      if (j <= i) return;
      if (const auto c = collision_of(elements, i, j, glm::length(elements.position[i] - elements.position[j]), gap))
        found(*c);
    });
  }
}

// Any violating pair lies in the same or adjacent cells of this hash.
PointHash collision_hash(const Elements& elements, double gap) {
  return hash_over(elements, bounding_box(elements), largest_diameter(elements) + gap);
}

}  // namespace

CollisionTally count_collisions(const Elements& elements, double gap) {
  const PointHash hash = collision_hash(elements, gap);
  const int n = int(elements.size());
  std::vector<CollisionTally> tallies(std::size_t(chunk_count(n)));
  for_each_chunk(n, [&](int chunk, int begin, int end) {
    collisions_from(hash, elements, gap, begin, end,
                    [&](const Collision& c) { add_to(tallies[std::size_t(chunk)], c); });
  });
  return total_of(tallies);
}

std::vector<Collision> find_collisions(const Elements& elements, double gap) {
  const PointHash hash = collision_hash(elements, gap);
  const int n = int(elements.size());
  std::vector<std::vector<Collision>> parts(std::size_t(chunk_count(n)));
  for_each_chunk(n, [&](int chunk, int begin, int end) {
    std::vector<Collision>& part = parts[std::size_t(chunk)];
    collisions_from(hash, elements, gap, begin, end, [&](const Collision& c) { part.push_back(c); });
    std::sort(part.begin(), part.end(),
              [](const Collision& a, const Collision& b) { return a.i != b.i ? a.i < b.i : a.j < b.j; });
  });
  return joined(parts);
}

namespace {

// Per element and per figure k < K, the smallest `score(i, j, distance)[k]` over all other
// elements, found without visiting all pairs: the 27 cells around each element, cells two largest
// diameters wide at first (tight patterns find their nearest neighbour there). Every element
// outside them is at least one cell away, so a score at or below `floor(i, cell)[k]` (the least
// score a pair that far apart can have) is the true minimum; the elements left (loose ones, or
// none found) search again in cells four times wider, until the cells span the whole set. O(n)
// for tight patterns, O(n log(spread)) for loose ones, never all pairs. +inf for an element alone.
// `first_pass(chunk, i, j, distance)` also sees every pair of the first pass (whose cells hold
// every pair within two largest diameters) both ways, (i, j) and (j, i), from i's chunk of
// [0, n), in no particular order.
template <std::size_t K, class Score, class Floor, class FirstPass>
std::array<std::vector<double>, K> smallest_over_others(const Elements& elements, Score score, Floor floor,
                                                        FirstPass first_pass) {
  const int n = int(elements.size());
  std::array<std::vector<double>, K> best;
  for (auto& b : best) b.assign(std::size_t(n), std::numeric_limits<double>::infinity());
  if (n < 2) return best;
  const Box box = bounding_box(elements);
  const double extent = box.largest_side();
  std::vector<int> pending(n);
  for (int i = 0; i < n; ++i) pending[i] = i;
  bool first = true;
  for (double width = 2 * largest_diameter(elements); !pending.empty(); width *= 4) {
    const PointHash hash = hash_over(elements, box, width);
    const bool spans_all = hash.cell() >= extent;
    const int m = int(pending.size());
    std::vector<std::vector<int>> unresolved(std::size_t(chunk_count(m)));
    for_each_chunk(m, [&](int chunk, int begin, int end) {
      for (int k = begin; k < end; ++k) {
        const int i = pending[std::size_t(k)];
        hash.for_each_near(elements.position[i], [&](int j) {
          if (j == i) return;
          const double d = glm::length(elements.position[i] - elements.position[j]);
          if (first) first_pass(chunk, i, j, d);
          const std::array<double, K> s = score(i, j, d);
          for (std::size_t f = 0; f < K; ++f) best[f][i] = std::min(best[f][i], s[f]);
        });
        if (spans_all) continue;
        const std::array<double, K> least = floor(i, hash.cell());
        bool resolved = true;
        for (std::size_t f = 0; f < K; ++f) resolved = resolved && best[f][i] <= least[f];
        if (!resolved) unresolved[std::size_t(chunk)].push_back(i);
      }
    });
    pending = joined(unresolved);
    first = false;
  }
  return best;
}

// Figures for smallest_over_others: a score for a pair `d` apart, and the least score of a pair at
// least `cell` apart. This one: the distance over the pair's radii plus `gap`.
struct NeighbourRatio {
  const Elements& e;
  double largest, gap;
  double score(int i, int j, double d) const { return d / contact_distance(e.diameter[i], e.diameter[j], gap); }
  double floor(int i, double cell) const { return cell / contact_distance(e.diameter[i], largest, gap); }
};
// The free space between the footprints.
struct Clearance {
  const Elements& e;
  double largest;
  double score(int i, int j, double d) const { return clearance_between(d, e.diameter[i], e.diameter[j]); }
  double floor(int i, double cell) const { return clearance_between(cell, e.diameter[i], largest); }
};
// The distance between two V-elements (+inf for any other pair).
struct VertexDistance {
  const Elements& e;
  bool vertex(int i) const { return e.kind[i] == ElementKind::Vertex; }
  double score(int i, int j, double d) const {
    return vertex(i) && vertex(j) ? d : std::numeric_limits<double>::infinity();
  }
  double floor(int i, double cell) const { return vertex(i) ? cell : std::numeric_limits<double>::infinity(); }
};

template <class Figure>
std::vector<double> smallest_over_others(const Elements& elements, const Figure& figure) {
  return smallest_over_others<1>(
      elements, [&](int i, int j, double d) { return std::array<double, 1>{figure.score(i, j, d)}; },
      [&](int i, double cell) { return std::array<double, 1>{figure.floor(i, cell)}; }, [](int, int, int, double) {})[0];
}

}  // namespace

std::vector<double> nearest_neighbor_ratios(const Elements& elements, double gap) {
  return smallest_over_others(elements, NeighbourRatio{elements, largest_diameter(elements), gap});
}

std::vector<double> nearest_clearances(const Elements& elements) {
  return smallest_over_others(elements, Clearance{elements, largest_diameter(elements)});
}

ProximityFigures measure_proximity(const Elements& elements, double gap) {
  ProximityFigures figures;
  const double largest = largest_diameter(elements);
  // The first pass's cells, two largest diameters wide, hold every colliding pair when the gap is
  // at most one largest diameter; a wider gap counts in a hash of its own.
  const bool count_in_first_pass = gap <= largest;
  const int n = int(elements.size());
  std::vector<CollisionTally> tallies(std::size_t(chunk_count(n)));
  const NeighbourRatio ratio{elements, largest, 0};
  const Clearance clearance{elements, largest};
  auto nearest = smallest_over_others<2>(
      elements,
      [&](int i, int j, double d) { return std::array<double, 2>{ratio.score(i, j, d), clearance.score(i, j, d)}; },
      [&](int i, double cell) { return std::array<double, 2>{ratio.floor(i, cell), clearance.floor(i, cell)}; },
      [&](int chunk, int i, int j, double d) {
        if (!count_in_first_pass || j <= i) return;
        if (const auto c = collision_of(elements, i, j, d, gap)) add_to(tallies[std::size_t(chunk)], *c);
      });
  figures.neighbor_ratios = std::move(nearest[0]);
  figures.clearances = std::move(nearest[1]);
  figures.collisions = count_in_first_pass ? total_of(tallies) : count_collisions(elements, gap);
  return figures;
}

std::vector<int> vertex_valences(const Elements& elements, double shell) {
  const int n = int(elements.size());
  std::vector<int> valence(n, -1);
  const VertexDistance distance{elements};
  const auto is_vertex = [&](int i) { return distance.vertex(i); };
  const std::vector<double> nearest = smallest_over_others(elements, distance);
  std::vector<double> finite;
  for (int i = 0; i < n; ++i)
    if (is_vertex(i) && std::isfinite(nearest[i])) finite.push_back(nearest[i]);
  if (finite.empty()) {
    for (int i = 0; i < n; ++i)
      if (is_vertex(i)) valence[i] = 0;
    return valence;
  }
  std::nth_element(finite.begin(), finite.begin() + finite.size() / 2, finite.end());
  const double reach = 1.5 * finite[finite.size() / 2];
  const PointHash hash = hash_over(elements, bounding_box(elements), shell * reach);
  for_each_chunk(n, [&](int, int begin, int end) {
    for (int i = begin; i < end; ++i) {
      if (!is_vertex(i)) continue;
      valence[i] = 0;
      if (!(nearest[i] <= reach)) continue;
      hash.for_each_near(elements.position[i], [&](int j) {
        if (j != i && is_vertex(j) && glm::length(elements.position[i] - elements.position[j]) <= shell * nearest[i])
          ++valence[i];
      });
    }
  });
  return valence;
}

}  // namespace paver
