#pragma once
// Chooses the solver backend by name for the CLI and the studio: cpu, vulkan, or auto (Vulkan
// when a GPU is present, else the CPU). Vulkan gets a compute context of its own, so the solver
// may run on any thread without sharing a queue with a renderer.
#include "solver/solver_backend.h"

#include <string>

namespace paver::app {

struct BackendChoice {
  SolverFactory factory;  // empty: the CPU reference
  std::string name;       // "cpu" or "vulkan"
  std::string device;     // the Vulkan device's name, when Vulkan
};

// `backend` is "cpu", "vulkan" or "auto"; `device` (a substring of a device name) may be empty.
// Throws InputError for any other backend name, and when Vulkan is asked for (`vulkan`, or a
// named device) but no such device can be made: a typo never falls back silently.
BackendChoice choose_backend(const std::string& backend, const std::string& device, int threads);

}  // namespace paver::app
