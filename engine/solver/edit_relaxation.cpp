#include "solver/edit_relaxation.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace paver {
namespace {

// Discs (centre, radius) bucketed by cells of the largest radius, so that a point looks at 3 x 3 cells.
class DiscGrid {
public:
  explicit DiscGrid(double cell) : cell_(cell) {}

  void add(glm::dvec2 centre, double radius) {
    discs_.push_back({centre, radius});
    cells_[key(index(centre.x), index(centre.y))].push_back(int(discs_.size()) - 1);
  }

  template <class Visit>
  void for_each_covering(glm::dvec2 p, const Visit& visit) const {
    const std::int64_t cx = index(p.x), cy = index(p.y);
    for (std::int64_t dy = -1; dy <= 1; ++dy)
      for (std::int64_t dx = -1; dx <= 1; ++dx) {
        const auto it = cells_.find(key(cx + dx, cy + dy));
        if (it == cells_.end()) continue;
        for (const int d : it->second) {
          const double distance = glm::length(p - discs_[std::size_t(d)].first);
          if (distance < discs_[std::size_t(d)].second) visit(d, distance);
        }
      }
  }

private:
  std::int64_t index(double x) const { return std::int64_t(std::floor(x / cell_)); }
  static std::int64_t key(std::int64_t x, std::int64_t y) { return x * 73856093 ^ y * 19349663; }

  double cell_;
  std::vector<std::pair<glm::dvec2, double>> discs_;
  std::unordered_map<std::int64_t, std::vector<int>> cells_;
};

// 1 at the centre, 0 from the edge of reach on, with zero slope at both ends.
double falloff(double x) {
  const double s = std::clamp(1 - x * x, 0.0, 1.0);
  return s * s;
}

}  // namespace

void set_aside_added(SpringSystem& system, const std::vector<EditedParticle>& edited) {
  for (const EditedParticle& e : edited)
    if (e.added) system.stray_count[std::size_t(e.particle)] = kRetired;
}

HeldParticles place_edits(SpringSystem& system, const std::vector<EditedParticle>& edited, double spacing,
                          bool carry) {
  HeldParticles held;
  if (edited.empty()) return held;
  // Each edit's reach, around where the particle was and where it goes.
  std::vector<glm::dvec2> from(edited.size()), drag(edited.size());
  std::vector<double> reach(edited.size());
  double largest = 0;
  for (std::size_t e = 0; e < edited.size(); ++e) {
    from[e] = edited[e].added ? edited[e].to : glm::dvec2(system.position[std::size_t(edited[e].particle)]);
    drag[e] = edited[e].to - from[e];
    reach[e] = std::max(kEditReach * spacing, kEditFalloff * glm::length(drag[e]));
    largest = std::max(largest, reach[e]);
  }
  DiscGrid sources(largest), sites(largest);
  for (std::size_t e = 0; e < edited.size(); ++e) {
    sources.add(from[e], reach[e]);
    sites.add(from[e], reach[e]);
    sites.add(edited[e].to, reach[e]);
  }
  std::vector<std::uint8_t> edited_particle(system.position.size(), 0);
  for (const EditedParticle& e : edited) edited_particle[std::size_t(e.particle)] = 1;
  for (int i = 0; i < system.particle_count(); ++i) {
    const std::size_t p = std::size_t(i);
    if (edited_particle[p] || !particle_moves(system.stray_count[p])) continue;
    glm::dvec2 moved(system.position[p]);
    const glm::dvec2 at = moved;
    sources.for_each_covering(at, [&](int d, double distance) {
      if (carry && !edited[std::size_t(d)].added)
        moved += drag[std::size_t(d)] * falloff(distance / reach[std::size_t(d)]);
    });
    system.position[p] = glm::vec2(moved);
    bool near = false;
    sites.for_each_covering(moved, [&](int, double) { near = true; });
    if (!near) {
      held.emplace_back(i, system.stray_count[p]);
      system.stray_count[p] = kPinned;
    }
  }
  for (const EditedParticle& e : edited) {
    const std::size_t p = std::size_t(e.particle);
    system.position[p] = glm::vec2(e.to);
    // A moved particle is the designer's even where the design's run had retired it.
    system.stray_count[p] = e.held ? kPinned : 0u;
  }
  return held;
}

void release_held(SpringSystem& system, const HeldParticles& held) {
  for (const auto& [particle, own] : held) system.stray_count[std::size_t(particle)] = own;
}

}  // namespace paver
