#pragma once
// Ctrl-C and SIGTERM for `paver run`: the first one sets a flag that every stage of the pipeline
// polls (the run stops within a moment, removes its staging folder and leaves the output folder
// as it was). Another one a second or more later ends the process at once (its staging folder is
// removed by the next run). Repeats closer than that are the same request: a terminal signals the
// whole process group and wrappers such as `timeout` pass a signal on twice.
#include <atomic>

namespace paver::cli {

void install_interrupt_handlers();
const std::atomic<bool>& interrupt_requested();

}  // namespace paver::cli
