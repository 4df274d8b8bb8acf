#pragma once
// The trimmed pattern as a mass-spring system (section 5), built once and stepped many times.
// Structs of arrays in float32; CSR neighbour lists so each particle gathers its forces without
// atomics. Every array maps one-to-one to an SSBO of the Vulkan solver.
#include "pattern/pattern.h"
#include "solver/solver_contract.h"

#include <glm/vec2.hpp>

#include <cstdint>
#include <vector>

namespace paver {

struct SpringSystem {
  // Particles.
  std::vector<glm::vec2> position;              // #P current positions in the map's frame
  // A leaky count of the particle's pull-backs onto the map (+2 per pull back, -1 per iteration
  // without); one pushed out persistently is retired (kRetired): it would be eliminated at the
  // boundary anyway, and held there it would only jam the pattern behind it.
  std::vector<std::uint32_t> stray_count;       // #P
  std::vector<std::int32_t> triangle_hint;      // #P triangle of M^ the particle was last in (-1: none)
  // CSR: the springs of particle a are neighbor_spring[neighbor_start[a] .. neighbor_start[a+1]),
  // leading to particles neighbor[...].
  std::vector<std::int32_t> neighbor_start;     // #P + 1
  std::vector<std::int32_t> neighbor;           // #2E
  std::vector<std::int32_t> neighbor_spring;    // #2E
  // Springs.
  std::vector<std::int32_t> spring_a, spring_b; // #E end particles
  std::vector<float> rest_length;               // #E D_ab, the length in the regular design
  std::vector<std::uint32_t> spring_flags;      // #E kSpringVirtual | kSpringContact
  // Filter state (eq. 15): the 2D target l^t of each spring, and l_ab at initialisation.
  std::vector<float> target;                    // #E
  std::vector<float> initial_target;            // #E

  int particle_count() const { return static_cast<int>(position.size()); }
  int spring_count() const { return static_cast<int>(spring_a.size()); }
};

// kRetired, kSpringVirtual and kSpringContact: solver/solver_contract.h (the GPU uses them too).

// Particles from the pattern's points, springs from its edges (virtual ones included).
// Targets are left at 0: the solver initialises them from the first lifting.
SpringSystem make_spring_system(const Pattern& pattern);

// Rebuilds the CSR lists after springs were added or removed.
void rebuild_neighbors(SpringSystem& system);

// Appends a spring (target 0: the solver initialises it); call rebuild_neighbors afterwards.
void add_spring(SpringSystem& system, int a, int b, float rest_length, std::uint32_t flags);

}  // namespace paver
