#pragma once
// As-rigid-as-possible parameterization (Liu et al. 2008, local/global) that stays bijective.
//
// Precompute once: per-triangle isometric 2D frames, cotangent weights, and the sparse Cholesky
// factorization of the global step's Laplacian (one vertex pinned). Each iteration is then a
// closed-form 2x2 rotation fit per triangle plus two back-substitutions.
//
// Plain ARAP can fold triangles and let the free boundary overlap itself. Here every step is a
// line search along (global solution - current map) that starts short of the first zero-area
// triangle (the smallest positive root of each triangle's signed-area quadratic) and is halved
// until the energy drops and the boundary does not cross itself. The energy it measures is ARAP
// plus a small barrier on |J^-1| so triangles cannot creep towards zero area. Starting from a
// bijective map, every iterate is bijective.
#include "map/map_quality.h"
#include "mesh/surface_mesh.h"

#include <glm/vec2.hpp>

#include <functional>
#include <string>
#include <memory>
#include <optional>
#include <vector>

namespace paver {

enum class ArapStart {
  Auto,   // LSCM when it is bijective, else the Tutte embedding
  Lscm,   // LSCM (throws if it is not bijective)
  Tutte,  // mean-value Tutte embedding on a circle
};

struct ArapOptions {
  ArapStart start = ArapStart::Auto;
  int max_iterations = 300;          // local/global iterations; default 300
  double tolerance = 1e-7;           // stop when the relative energy decrease is below this
  double barrier_weight = 1e-3;      // weight of the inverse-Jacobian barrier in the line search
  bool injective = true;             // false = plain ARAP (full steps; for comparison only)
};

struct ArapReport {
  ArapStart start_used = ArapStart::Tutte;
  int iterations = 0;
  double initial_energy = 0;
  double final_energy = 0;
  int blocked_steps = 0;             // iterations whose step was shortened to keep bijectivity
  double precompute_ms = 0;
  double solve_ms = 0;
};

struct Parameterization {
  std::vector<glm::dvec2> uv;        // #V parameter coordinates; 2D area equals 3D area
  // Where each hole's temporary patch had its centre, in the same frame: a point inside the
  // hole that sees all of its rim (the patch's fan never folds). A band's seamless map starts from it.
  std::vector<glm::dvec2> hole_centres;
  MapQuality quality;
  ArapReport report;
};

// The stateful solver: precompute once, iterate many times (e.g. in the background of the editor).
class ArapSolver {
public:
  ArapSolver(const SurfaceMesh& mesh, const ArapOptions& options);
  ~ArapSolver();
  ArapSolver(ArapSolver&&) noexcept;
  ArapSolver& operator=(ArapSolver&&) noexcept;

  // Runs up to `max_iterations` more iterations from the current map; returns true when converged.
  bool iterate(int max_iterations);
  const std::vector<glm::dvec2>& uv() const;
  double energy() const;
  const ArapReport& report() const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The result of a solver that has iterated: its map scaled to the surface's area and centred,
// and measured. For callers that iterate in chunks (the editor shows progress).
Parameterization finish_parameterization(const SurfaceMesh& mesh, const ArapSolver& solver);

// What a chunk's progress says: "ARAP 20 / 300, energy 0.00217768".
std::string arap_progress_text(int done, int max, double energy);

// One call: start map, ARAP to convergence, then finish_parameterization.
Parameterization parameterize_arap(const SurfaceMesh& mesh, const ArapOptions& options = {});

// The same, iterated a few steps at a time for long maps: `progress(done, max, energy)` after each chunk,
// and `stop()` polled between chunks (the start map's factorization cannot be interrupted).
// Returns nothing when stopped. The map equals parameterize_arap's, bit for bit.
std::optional<Parameterization> parameterize_arap(const SurfaceMesh& mesh, const ArapOptions& options,
                                                  const std::function<void(int done, int max, double energy)>& progress,
                                                  const std::function<bool()>& stop);

}  // namespace paver
