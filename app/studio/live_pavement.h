#pragma once
// run_pipeline (on a surface already mapped) on a background thread, watched and steered from the UI. The solver's observer
// publishes the particle positions for the live view and is where the run is steered:
//   pause  - the observer blocks on a condition variable until resumed;
//   step N - the run goes on until N more iterations are done, then pauses again (on the Vulkan
//            solver it stops at the first batch boundary past that);
//   reset  - the observer returns false, every later solve is stopped too, the result is dropped.
// A new run (the design changed) abandons the old one the same way; the UI never waits for it.
#include "background_jobs.h"

#include "pattern/pattern.h"
#include "pipeline/pavement.h"
#include "pipeline/run_pipeline.h"
#include "map/surface_map.h"

#include <glm/vec2.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace paver::studio {

enum class RunState { Idle, Running, Paused, Finished };

// The particles as the solver has them now, with what is needed to place elements on them.
struct LiveSnapshot {
  std::uint64_t revision = 0;             // the document revision the run is for
  std::uint64_t sequence = 0;             // bumps with every publication
  std::shared_ptr<const Pattern> pattern;
  Design design;                          // spacing resolved
  std::vector<glm::dvec2> points;         // #P, the map's frame
  int iteration = 0;
};

struct RunOutcome {
  std::uint64_t revision = 0;
  std::shared_ptr<const Pavement> pavement;  // null when the run failed
  std::string error;                         // why it failed
  bool input_error = false;                  // the design's fault (InputError), not a bug
  double milliseconds = 0;                   // wall time of the whole run
};

struct RunRequest {
  std::shared_ptr<const SurfaceMap> map;
  Design design;
  std::uint64_t revision = 0;
  SolverFactory solver;                 // empty: the CPU reference
  bool paused = false;                  // start paused after the first iteration (for stepping)
  int step = 0;                         // with paused: iterations to let through first
  std::shared_ptr<const ShapeMesh> custom_shape;  // the design's custom shape, already read; else the run reads it
};

class LivePavement {
public:
  LivePavement() = default;
  // Abandons the run, so a paused worker wakes and the thread can be joined.
  ~LivePavement();
  LivePavement(const LivePavement&) = delete;
  LivePavement& operator=(const LivePavement&) = delete;
  void start(RunRequest request);   // abandons the run in progress
  void pause();
  void resume();
  void step(int iterations);        // lets `iterations` more through, then pauses
  void reset();                     // abandons the run and forgets it: Idle

  RunState state() const;
  std::uint64_t revision() const;   // of the current run, or the last one started (reset or not)
  int iteration() const;
  // The latest positions when newer than `sequence`.
  std::optional<LiveSnapshot> snapshot_since(std::uint64_t sequence) const;
  std::optional<RunOutcome> take_outcome();  // once, when the run has finished

  struct Run;  // shared with the worker thread

private:
  std::shared_ptr<Run> run_;
  std::uint64_t revision_ = 0;
  std::uint64_t runs_started_ = 0;
  BackgroundJobs jobs_;
};

}  // namespace paver::studio
