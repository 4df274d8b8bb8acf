#pragma once
// The memory this machine can give a job now: MemAvailable from /proc/meminfo (what the kernel
// can hand out without swapping), else the physical memory. For refusing work that would not fit.
namespace paver::app {

double available_memory_bytes();

}  // namespace paver::app
