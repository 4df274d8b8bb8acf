#pragma once
// Ctrl-C and SIGTERM for `paver run`: the first one sets a flag that every stage of the pipeline
// polls (the run stops within a moment, removes its staging folder and leaves the output folder
// as it was). Another one a second or more later ends the process at once (its staging folder is
// removed by the next run). Repeats closer than that are the same request: a terminal signals the
// whole process group and wrappers such as `timeout` pass a signal on twice.
#include <atomic>

namespace paver::cli {

void install_interrupt_handlers();

// Until writing starts a request ends the process at once (exit 130, "interrupted; nothing was
// written"): there is nothing to clean up, and the stages that cannot poll the flag (a sparse
// factorization of a large mesh takes seconds) would otherwise hold the stop up. Commands call
// nothing_written_yet() before their work and writing_starts() before they create any file; a
// request that already began ending the process makes writing_starts() wait for the end.
void nothing_written_yet();
void writing_starts();
const std::atomic<bool>& interrupt_requested();
// 128 + the signal that asked to stop: 130 for Ctrl-C, 143 for SIGTERM, as shells expect.
int interrupted_exit_code();

}  // namespace paver::cli
