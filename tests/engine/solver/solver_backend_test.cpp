// Which backend solves a system: routed_by_size hands a small system to one factory and a large
// one to the other (--backend auto on a GPU), and the pavement reports the backend that ran its
// main solve (the adaptive pattern's optimizer runs on the CPU whatever was asked).
#include "io/design_io.h"
#include "pipeline/pavement.h"
#include "solver/solver_backend.h"
#include "surface_maps.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace paver {
namespace {

// A backend that only says its name and how large a system it was given.
class NamedBackend : public SpringSolverBackend {
public:
  NamedBackend(std::string name, int particles) : name_(std::move(name)), particles_(particles) {}
  SolveReport solve(const SolverObserver&, const std::atomic<bool>*) override {
    SolveReport r;
    r.iterations = particles_;
    r.reason = StopReason::Converged;
    return r;
  }
  std::string_view backend_name() const override { return name_; }

private:
  std::string name_;
  int particles_;
};

SolverFactory named(const std::string& name) {
  return [name](const SolverSurface&, SpringSystem& system, const SolverParams&, double) {
    return std::unique_ptr<SpringSolverBackend>(new NamedBackend(name, system.particle_count()));
  };
}

TEST(SolverBackend, RoutedBySizeGivesSmallSystemsToOneAndLargeToTheOther) {
  const SolverFactory routed = routed_by_size(named("small"), named("large"), 400);
  const SolverSurface surface;
  const SolverParams params;
  for (const int particles : {0, 1, 399, 400, 401, 100000}) {
    SpringSystem system;
    system.position.assign(std::size_t(particles), glm::vec2(0));
    const auto solver = routed(surface, system, params, 1.0);
    EXPECT_EQ(solver->backend_name(), particles >= 400 ? "large" : "small") << particles << " particles";
    EXPECT_EQ(solver->solve({}, nullptr).iterations, particles) << "the system itself is handed on";
  }
}

TEST(SolverBackend, ThePavementSaysWhichBackendRanItsMainSolve) {
  const Design design = load_design(test::source_dir() / "assets/designs/pendant_tri_gems.json");
  const SurfaceMap& map = *test::bundled_map("pendant");
  PavementOptions options;
  EXPECT_EQ(make_pavement(map, design, options).solve.backend, "cpu");
  // The pendant's 186 particles go to the small side, the dome's 600 and more to the large one.
  options.solver = routed_by_size(cpu_solver_factory(), named("large"), 400);
  EXPECT_EQ(make_pavement(map, design, options).solve.backend, "cpu");
  Design dome = load_design(test::source_dir() / "assets/designs/dome_hex_d6.json");
  dome.pattern.topology = Topology::Lattice;  // the named backend moves nothing: auto would grow it instead
  EXPECT_EQ(make_pavement(*test::bundled_map("dome"), dome, options).solve.backend, "large");
  // The adaptive pattern's optimizer has no GPU path.
  Design adaptive = design;
  adaptive.pattern.topology = Topology::Adaptive;
  options.solver = named("large");
  EXPECT_EQ(make_pavement(map, adaptive, options).solve.backend, "cpu");
}

}  // namespace
}  // namespace paver
