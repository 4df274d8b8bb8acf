#include "solver/coarse_start.h"

#include "core/stopwatch.h"
#include "solver/displacement_field.h"
#include "solver/solver_kernels.h"


namespace paver {
namespace {

bool on_map(const SolverSurface& surface, glm::vec2 p) {
  glm::vec3 bary;
  return kernels::locate(surface, p, bary) >= 0;
}

struct Level {
  const SolverSurface& surface;
  const PatternAtSpacing& pattern_at;
  const SolverParams& params;
  const SolverFactory& factory;
  const std::atomic<bool>* stop;
  CoarseStartReport& report;

  bool stopped() const { return stop && stop->load(); }

  // Moves `position` (the lattice at `spacing`) by the field of the design relaxed at twice the
  // spacing; returns false when there was no coarser level (or it was stopped) and nothing moved.
  bool start(std::vector<glm::vec2>& position, std::vector<std::uint32_t>& stray_count, double spacing,
             int levels_left) {
    if (levels_left <= 0 || stopped()) return false;
    // A coarse level has about a quarter of the points: none worth relaxing below this, and not
    // built at all (at a spacing near the surface's size the coarser lattice would not fit).
    if (position.size() < 2 * std::size_t(kCoarseStartMinPoints)) return false;
    const double coarse_spacing = 2 * spacing;
    const Pattern coarse = pattern_at(coarse_spacing);
    if (coarse.point_count() < kCoarseStartMinPoints) return false;
    report.level_points.push_back(coarse.point_count());
    const std::size_t level = report.level_points.size() - 1;
    report.level_iterations.push_back(0);
    SpringSystem system = make_spring_system(coarse);
    start(system.position, system.stray_count, coarse_spacing, levels_left - 1);
    if (stopped()) return false;
    report.level_iterations[level] = factory(surface, system, params, coarse_spacing)->solve({}, stop).iterations;
    if (stopped()) return false;

    const glm::dvec2 lo(surface.grid_origin);
    const glm::dvec2 hi = lo + glm::dvec2(surface.grid_nx, surface.grid_ny) * double(surface.grid_cell_size);
    DisplacementField field(lo, hi, coarse_spacing);
    for (int i = 0; i < system.particle_count(); ++i)
      if (system.stray_count[i] != kRetired)
        field.add(coarse.points[i], glm::dvec2(system.position[i]) - coarse.points[i]);
    field.finish();
    for (std::size_t i = 0; i < position.size(); ++i) {
      if (!particle_moves(stray_count[i])) continue;  // retired, or pinned by the designer
      const glm::vec2 moved = glm::vec2(glm::dvec2(position[i]) + field.at(glm::dvec2(position[i])));
      // Every particle starts on the map (the pattern is trimmed to it; earlier levels only move
      // particles onto it), so one moved off it found no room where the coarse pattern thinned out.
      if (on_map(surface, moved))
        position[i] = moved;
      else
        stray_count[i] = kRetired;
    }
    return true;
  }
};

}  // namespace

CoarseStartReport coarse_start(const SolverSurface& surface, SpringSystem& system, const PatternAtSpacing& pattern_at,
                               const SolverParams& params, double spacing, const SolverFactory& factory,
                               const std::atomic<bool>* stop) {
  CoarseStartReport report;
  if (params.coarse_levels <= 0 || surface.period > 0) return report;
  const Stopwatch watch;
  // Work on copies: a stop part-way leaves the system as it was.
  std::vector<glm::vec2> position = system.position;
  std::vector<std::uint32_t> stray_count = system.stray_count;
  Level level{surface, pattern_at, params, factory, stop, report};
  if (level.start(position, stray_count, spacing, params.coarse_levels) && !level.stopped()) {
    for (std::size_t i = 0; i < stray_count.size(); ++i)
      if (stray_count[i] == kRetired && system.stray_count[i] != kRetired) ++report.retired;
    system.position = std::move(position);
    system.stray_count = std::move(stray_count);
  } else {
    report.level_points.clear();  // stopped: nothing of the levels was used
    report.level_iterations.clear();
  }
  report.milliseconds = watch.milliseconds();
  return report;
}

}  // namespace paver
