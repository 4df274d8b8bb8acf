#pragma once
// The bijective map of a surface to the plane (section 4.2): a bijective start map (LSCM or
// Tutte), then a descent that never leaves the bijective maps, on one of two energies.
//
// - Symmetric Dirichlet (the default), sum A_t (|J|^2 + |J^-1|^2): infinite at a collapsed
//   triangle, so it is its own barrier. Each step solves SLIM's reweighted proxy (Rabinovich et
//   al. 2017, made isotropic so u and v share one factorization of the Laplacian's pattern) with
//   the exact gradient on the right. On a nearly closed head, whose start map squeezes triangles
//   to almost no area, it converges in tens of iterations where ARAP crawls.
// - ARAP (the paper's; Liu et al. 2008), local/global: the Laplacian is factorized once and each
//   iteration is a closed-form rotation fit per triangle plus two back-substitutions; a small
//   barrier on |J^-1| joins its energy so triangles cannot creep towards zero area. A surface with
//   holes, a band and a closed surface's charts keep it (map_options_for).
//
// Every step of either is a line search along (proxy solution - current map) that starts short
// of the first zero-area triangle (the smallest positive root of each triangle's signed-area
// quadratic) and is halved until the energy drops and the boundary does not cross itself.
// Starting from a bijective map, every iterate is bijective.
#include "map/map_quality.h"
#include "mesh/surface_mesh.h"

#include <glm/vec2.hpp>

#include <functional>
#include <string>
#include <string_view>
#include <memory>
#include <optional>
#include <vector>

namespace paver {

enum class MapStart {  // named in this order by kStartNaming (bijective_map.cpp)
  Auto,   // LSCM when it is bijective, else the Tutte embedding
  Lscm,   // LSCM (throws if it is not bijective)
  Tutte,  // mean-value Tutte embedding on a circle
};

enum class MapEnergy {  // named in this order by kEnergyNaming (bijective_map.cpp)
  SymmetricDirichlet,  // sum A_t (|J|^2 + |J^-1|^2), minimized by SLIM (Rabinovich et al. 2017)
  Arap,                // the paper's ARAP (Liu et al. 2008), local/global with a barrier
};

struct MapOptions {
  MapEnergy energy = MapEnergy::SymmetricDirichlet;
  MapStart start = MapStart::Auto;
  int max_iterations = 300;
  // Stop when the energy fell by less than this fraction of itself per iteration, averaged over
  // the last kStopWindow iterations; 0 takes the energy's own (below).
  double tolerance = 0;
  static constexpr int kStopWindow = 5;
  static constexpr double kSymmetricDirichletTolerance = 1e-4;
  static constexpr double kArapTolerance = 1e-7;  // its steps are short on hard surfaces
  double barrier_weight = 1e-3;      // ARAP only: weight of the inverse-Jacobian barrier in the line search
  bool injective = true;             // ARAP only: false = plain ARAP (full steps; for comparison only)
};

// The energy and the start as the summaries name them ("symmetric Dirichlet", "LSCM") and as
// report.json keys them ("symmetric_dirichlet", "lscm"), written once here.
std::string_view map_energy_name(MapEnergy energy);
std::string_view map_energy_key(MapEnergy energy);
std::string_view map_start_name(MapStart start);
std::string_view map_start_key(MapStart start);

struct MapReport {
  MapEnergy energy = MapEnergy::SymmetricDirichlet;
  MapStart start_used = MapStart::Tutte;
  int iterations = 0;
  double initial_energy = 0;
  double final_energy = 0;
  int blocked_steps = 0;             // iterations whose step was shortened to keep bijectivity
  int factorizations = 0;            // ARAP: 1 (its Laplacian); symmetric Dirichlet: proxies factorized (at most one more than iterations)
  double precompute_ms = 0;
  double solve_ms = 0;
  bool planar = false;               // a flat surface, projected onto its plane (planar_map.h): no descent
};

// How the summaries name the method ("symmetric Dirichlet from LSCM", "the projection onto its
// plane") and report.json keys it ("symmetric_dirichlet", "planar").
std::string map_method_name(const MapReport& report);
std::string_view map_method_key(const MapReport& report);

struct Parameterization {
  std::vector<glm::dvec2> uv;        // #V parameter coordinates; 2D area equals 3D area
  // Where each hole's temporary patch had its centre, in the same frame: a point inside the
  // hole that sees all of its rim (the patch's fan never folds). A band's seamless map starts from it.
  std::vector<glm::dvec2> hole_centres;
  MapQuality quality;
  MapReport report;
};

// The stateful solver: precompute once, iterate many times (e.g. in the background of the editor).
class MapSolver {
public:
  MapSolver(const SurfaceMesh& mesh, const MapOptions& options);
  ~MapSolver();
  MapSolver(MapSolver&&) noexcept;
  MapSolver& operator=(MapSolver&&) noexcept;

  // Runs up to `max_iterations` more iterations from the current map; returns true when converged.
  bool iterate(int max_iterations);
  const std::vector<glm::dvec2>& uv() const;
  double energy() const;
  const MapReport& report() const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The result of a solver that has iterated: its map scaled to the surface's area and centred,
// and measured. For callers that iterate in chunks (the editor shows progress).
Parameterization finish_parameterization(const SurfaceMesh& mesh, const MapSolver& solver);

// What a chunk's progress says: "20 / 300 iterations, energy 4.02347".
std::string map_progress_text(int done, int max, double energy);

// What is being mapped: an open surface, or one chart of a closed surface's atlas.
enum class MapPiece { Surface, Chart };

// The options `paver run` maps `mesh` with: symmetric Dirichlet for a disk (one boundary loop);
// the paper's ARAP for more loops, where the map closes the holes with invented triangles
// (hole_patches.h), and for a closed surface's charts. Measured (docs/parameterization.md):
// - a band's seamless map unrolls its annulus map log-polar around the hole, and the symmetric
//   Dirichlet map of the scanned bunnyhead_band folds under that unroll;
// - on bunnyhead_three_loops (two holes) the adaptive hex pavement keeps fill 1.01-1.05 on the
//   ARAP map against 0.94-0.97 on the symmetric Dirichlet one, at four spacings;
// - a chart is half a closed surface, where ARAP converges; the closed bunny's tri pavement at a
//   gap of 8% of D keeps fill 0.852 on ARAP charts against 0.846 on symmetric Dirichlet ones.
MapOptions map_options_for(const SurfaceMesh& mesh, MapPiece piece = MapPiece::Surface);

// One call: start map, descent to convergence, then finish_parameterization. A flat surface with
// the automatic start is projected onto its plane instead (planar_map.h): the same for both calls.
Parameterization parameterize_surface(const SurfaceMesh& mesh, const MapOptions& options = {});

// The same, iterated a few steps at a time for long maps: `progress(done, max, energy)` after each chunk,
// and `stop()` polled between chunks (the start map's factorization cannot be interrupted).
// Returns nothing when stopped. The map equals parameterize_surface's, bit for bit.
std::optional<Parameterization> parameterize_surface(const SurfaceMesh& mesh, const MapOptions& options,
                                                  const std::function<void(int done, int max, double energy)>& progress,
                                                  const std::function<bool()>& stop);

}  // namespace paver
