#pragma once
// Ctrl-C and SIGTERM for `paver run`: the first one sets a flag that every stage of the pipeline
// polls (the run stops within a moment, removes its staging folder and leaves the output folder
// as it was); a second one ends the process at once (its staging folder is removed by the next run).
#include <atomic>

namespace paver::cli {

void install_interrupt_handlers();
const std::atomic<bool>& interrupt_requested();

}  // namespace paver::cli
