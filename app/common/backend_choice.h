#pragma once
// Chooses the solver backend by name for the CLI and the studio: cpu, vulkan, or auto (on a GPU,
// Vulkan for systems of kAutoGpuLeastParticles particles and more and the CPU below; else the
// CPU). Vulkan gets a compute context of its own, so the solver may run on any thread without
// sharing a queue with a renderer.
#include "solver/solver_backend.h"

#include <string>

namespace paver::app {

// Measured on an NVIDIA H100 machine against its 16 CPU cores, whole pavements, median of three
// (`paver-backend-bench --sweep`, docs/benchmarks.md): a solve on the GPU has a fixed cost
// (uploads, two submissions), so the GPU was slower up to 293 particles (1.02x the CPU's time
// there, 1.11x on the 186-particle pendant) and faster from 304 (0.96x) and 345 (0.64x) on, but
// for the bangle (744 particles, 1.27x), whose solve settles in 27 iterations.
inline constexpr int kAutoGpuLeastParticles = 300;

struct BackendChoice {
  SolverFactory factory;  // empty: the CPU reference
  std::string name;       // "cpu", "vulkan", or "auto" (both, by size)
  std::string device;     // the Vulkan device's name, when Vulkan
};

// `backend` is "cpu", "vulkan" or "auto"; `device` (a substring of a device name) may be empty.
// Throws InputError for any other backend name, and when Vulkan is asked for (`vulkan`, or a
// named device) but no such device can be made: a typo never falls back silently.
BackendChoice choose_backend(const std::string& backend, const std::string& device, int threads);

}  // namespace paver::app
