#pragma once
// What `paver run` and `paver param` are doing, on stderr, for anything that can take seconds
// (loading, mapping with the map's energy, pattern, optimizer, resolution, refill, export).
// On a terminal: one line redrawn in place (stage, bar, detail) at most 20 times a second and
// cleared at the end. Elsewhere (logs, pipes): a line when a stage starts and a detail line at
// most every 2 s, with no control characters. Nothing at all when quiet (--quiet).
#include "pipeline/map_surface.h"
#include "solver/solver_backend.h"

#include <chrono>
#include <string>

namespace paver::cli {

class Progress {
public:
  Progress(bool quiet, bool terminal);
  ~Progress();  // clears the terminal line
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // A stage starts; `name` as in the report's timings ("resolve_collisions" reads "resolve collisions").
  void stage(const std::string& name);
  // How far the current stage is, in [0, 1], and what it is doing.
  void fraction(double done, const std::string& detail);
  void finish();

  // Feeds the loader's and the map's progress ("mapping: 20 / 300 iterations, energy ...").
  PipelineProgress mapping();
  // Feeds the solver's iterations into the current stage.
  SolverObserver solver(int iterations);

private:
  void draw(double done, const std::string& detail);

  bool quiet_, terminal_;
  bool drawn_ = false;
  std::string stage_;
  std::chrono::steady_clock::time_point last_;
};

// Whether stderr is a terminal.
bool stderr_is_terminal();

}  // namespace paver::cli
