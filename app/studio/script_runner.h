#pragma once
// Runs a parsed script against the studio, one command per frame, as a user would: through the
// same actions the panels use. Commands that need the studio to get somewhere (a surface loaded,
// the pavement final and on screen, a screenshot written) hold the script until it has. A failing
// command, or any error the studio reports meanwhile, prints the error and ends the session.
#include "script.h"
#include "studio.h"

#include <chrono>
#include <string>
#include <vector>

namespace paver::studio {

class ScriptRunner {
public:
  ScriptRunner(std::vector<ScriptCommand> commands, std::string source);

  // Once per frame, after update_studio and before the UI is drawn.
  void frame(Studio& s);
  bool finished() const { return finished_; }
  int exit_code() const { return exit_code_; }

private:
  enum class Phase { Ready, Settling };  // waiting to start the command / for it to take effect
  bool ready(const Studio& s, const ScriptCommand& c) const;
  void act(Studio& s, const ScriptCommand& c);
  bool settled(Studio& s, const ScriptCommand& c);
  void fail(Studio& s, const std::string& message, int code);

  std::vector<ScriptCommand> commands_;
  std::string source_;
  std::size_t next_ = 0;
  std::string status_said_;                   // the status line last written to the log
  Phase phase_ = Phase::Ready;
  int frames_left_ = 0;                       // wait N, orbit
  float orbit_step_ = 0;                      // orbit: radians per frame
  int typing_since_frame_ = 0;                // type: the frame its input began
  std::chrono::steady_clock::time_point since_;  // the current command started waiting
  int errors_seen_ = 0;
  bool finished_ = false;
  int exit_code_ = 0;
};

}  // namespace paver::studio
