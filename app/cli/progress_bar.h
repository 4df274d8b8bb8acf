#pragma once
// A one-line progress bar for the solver on a terminal (stderr), fed by the solver's observer.
#include "solver/solver_backend.h"

namespace paver::cli {

// An observer that redraws `[#####.....] 120/200` on stderr; empty when stderr is no terminal
// (logs and pipes get no control characters).
SolverObserver terminal_progress_bar(int iterations);

// Ends the bar's line, if one was drawn.
void finish_progress_bar();

}  // namespace paver::cli
