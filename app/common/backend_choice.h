#pragma once
// Chooses the solver backend by name for the CLI and the studio: cpu, vulkan, or auto (on a GPU,
// Vulkan for systems of kAutoGpuLeastParticles particles and more and the CPU below; else the
// CPU). Vulkan gets a compute context of its own, so the solver may run on any thread without
// sharing a queue with a renderer.
#include "solver/solver_backend.h"

#include <string>

namespace paver::app {

// Measured on an NVIDIA H100 machine against its 16 CPU cores (docs/benchmarks.md): a solve on the
// GPU costs about 7 ms whatever its size (uploads, two submissions), so the bundled pendant's 186
// particles took 67-80 ms there against 42 ms on the CPU, while the torus's 479 took 77-88 ms
// against 95 and the wave's 543 (3,000 iterations) 179-205 ms against 385.
inline constexpr int kAutoGpuLeastParticles = 400;

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
