#include "solver/spring_system.h"

#include "core/contact_rule.h"

namespace paver {

void rebuild_neighbors(SpringSystem& sys) {
  const int n = sys.particle_count(), e = sys.spring_count();
  sys.neighbor_start.assign(n + 1, 0);
  for (int s = 0; s < e; ++s) ++sys.neighbor_start[sys.spring_a[s] + 1], ++sys.neighbor_start[sys.spring_b[s] + 1];
  for (int a = 0; a < n; ++a) sys.neighbor_start[a + 1] += sys.neighbor_start[a];
  sys.neighbor.resize(2 * size_t(e));
  sys.neighbor_spring.resize(2 * size_t(e));
  std::vector<std::int32_t> fill(sys.neighbor_start.begin(), sys.neighbor_start.end() - 1);
  // Springs in index order: each particle's list is sorted by spring index, which fixes the
  // summation order of its forces on every backend.
  for (int s = 0; s < e; ++s) {
    const int a = sys.spring_a[s], b = sys.spring_b[s];
    sys.neighbor[fill[a]] = b, sys.neighbor_spring[fill[a]++] = s;
    sys.neighbor[fill[b]] = a, sys.neighbor_spring[fill[b]++] = s;
  }
}

void add_spring(SpringSystem& sys, int a, int b, float rest_length, std::uint32_t flags) {
  sys.spring_a.push_back(a);
  sys.spring_b.push_back(b);
  sys.rest_length.push_back(rest_length);
  sys.spring_flags.push_back(flags);
  sys.target.push_back(0.0f);
  sys.initial_target.push_back(0.0f);
}

SpringSystem make_spring_system(const Pattern& pattern) {
  SpringSystem sys;
  sys.position.reserve(pattern.points.size());
  for (const auto& p : pattern.points) sys.position.emplace_back(float(p.x), float(p.y));
  sys.stray_count.assign(pattern.points.size(), 0u);
  sys.triangle_hint.assign(pattern.points.size(), -1);
  const int e = pattern.edge_count();
  sys.spring_a.assign(pattern.edge_a.begin(), pattern.edge_a.end());
  sys.spring_b.assign(pattern.edge_b.begin(), pattern.edge_b.end());
  sys.rest_length.resize(e);
  sys.spring_flags.resize(e);
  for (int s = 0; s < e; ++s) {
    // Aimed just past the lattice length: where that length is the contact distance (touching
    // elements), a spring settled within the solver's tolerance must still land on the right side.
    sys.rest_length[s] = float(pattern.edge_rest_length[s] * (1 + kContactAim));
    sys.spring_flags[s] = pattern.edge_virtual[s] ? kSpringVirtual : 0u;
  }
  sys.target.assign(e, 0.0f);
  sys.initial_target.assign(e, 0.0f);
  rebuild_neighbors(sys);
  return sys;
}

}  // namespace paver
