#include "map/surface_particles.h"

#include "map/uv_from_tangent.h"

#include <glm/geometric.hpp>

namespace paver {

std::vector<int> SurfaceParticles::lift_dropping_outside(const SurfaceMap& map) {
  lifted.resize(uv.size());
  lift_points(map, uv, lifted);
  std::vector<int> kept;
  for (int i = 0; i < size(); ++i)
    if (lifted.triangle[i] >= 0) {
      const int k = int(kept.size());
      uv[k] = uv[i];
      lifted.triangle[k] = lifted.triangle[i];
      lifted.position[k] = lifted.position[i];
      lifted.normal[k] = lifted.normal[i];
      lifted.curvature[k] = lifted.curvature[i];
      kept.push_back(i);
    }
  uv.resize(kept.size());
  lifted.resize(kept.size());
  return kept;
}

void SurfaceParticles::step(const SurfaceMap& map, std::vector<glm::dvec3> step) {
  std::vector<int> pending;
  std::vector<glm::dvec2> trial;
  for (int i = 0; i < size(); ++i) {
    if (lifted.triangle[i] < 0) continue;  // off the map: it does not move
    const glm::dvec3 n = lifted.normal[i];
    step[i] -= glm::dot(step[i], n) * n;
    if (glm::length(step[i]) > 0) {
      pending.push_back(i);
      trial.push_back(uv[i] + UvFromTangent(map, lifted.triangle[i])(step[i]));
    }
  }
  LiftedPoints moved;
  for (int attempt = 0; attempt < 5 && !pending.empty(); ++attempt) {
    moved.resize(trial.size());
    lift_points(map, trial, moved);
    std::vector<int> still;
    std::vector<glm::dvec2> again;
    for (size_t k = 0; k < pending.size(); ++k) {
      const int i = pending[k];
      if (moved.triangle[k] >= 0 &&
          glm::length(moved.position[k] - lifted.position[i]) <= 1.5 * glm::length(step[i])) {
        uv[i] = trial[k];
        lifted.triangle[i] = moved.triangle[k];
        lifted.position[i] = moved.position[k];
        lifted.normal[i] = moved.normal[k];
        lifted.curvature[i] = moved.curvature[k];
        continue;
      }
      still.push_back(i);
      again.push_back(uv[i] + 0.5 * (trial[k] - uv[i]));
    }
    pending.swap(still);
    trial.swap(again);
  }
}

void SurfaceParticles::keep_from_boundary(const SurfaceMap& map, const BoundaryIndex& boundary, double margin) {
  if (!(margin > 0)) return;  // no particle is nearer than 0
  std::vector<glm::dvec3> push(size(), glm::dvec3(0));
  for (int i = 0; i < size(); ++i) {
    if (lifted.triangle[i] < 0) continue;
    const BoundaryIndex::Nearest near = boundary.nearest(lifted.position[i]);
    if (near.distance >= margin) continue;
    const glm::dvec3 n = lifted.normal[i];
    glm::dvec3 away = lifted.position[i] - near.point;
    away -= glm::dot(away, n) * n;
    if (glm::length(away) > 0) push[i] = (margin - near.distance) * glm::normalize(away);
  }
  step(map, std::move(push));
}

}  // namespace paver
