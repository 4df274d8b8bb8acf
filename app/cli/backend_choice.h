#pragma once
// Chooses the solver backend by name for the CLI: cpu, vulkan, or auto (Vulkan when a GPU is
// present, else the CPU).
#include "paver/solver_backend.h"

#include <string>

namespace paver::cli {

struct BackendChoice {
  SolverFactory factory;  // empty: the CPU reference
  std::string name;       // "cpu" or "vulkan"
  std::string device;     // the Vulkan device's name, when Vulkan
};

// Throws InputError when `backend` is vulkan and no device can be made.
BackendChoice choose_backend(const std::string& backend, const std::string& device, int threads);

}  // namespace paver::cli
