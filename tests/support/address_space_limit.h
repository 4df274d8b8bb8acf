#pragma once
// Runs code with the process's address space capped a little above what it uses now, so that a
// large allocation fails with std::bad_alloc instead of quietly succeeding: a test can show that
// a reader refuses absurd counts before allocating for them. Linux only (/proc/self/statm).
#include <sys/resource.h>
#include <unistd.h>

#include <cstdint>
#include <fstream>

namespace paver::test {

class AddressSpaceLimit {
public:
  // Allows `extra_bytes` more than the current virtual size; active() says whether it took.
  explicit AddressSpaceLimit(std::uint64_t extra_bytes) {
    std::uint64_t pages = 0;
    std::ifstream statm("/proc/self/statm");
    if (!(statm >> pages) || getrlimit(RLIMIT_AS, &saved_) != 0) return;
    rlimit limited = saved_;
    limited.rlim_cur = pages * std::uint64_t(sysconf(_SC_PAGESIZE)) + extra_bytes;
    if (saved_.rlim_max != RLIM_INFINITY && limited.rlim_cur > saved_.rlim_max) return;
    active_ = setrlimit(RLIMIT_AS, &limited) == 0;
  }
  ~AddressSpaceLimit() {
    if (active_) setrlimit(RLIMIT_AS, &saved_);
  }
  AddressSpaceLimit(const AddressSpaceLimit&) = delete;
  AddressSpaceLimit& operator=(const AddressSpaceLimit&) = delete;

  bool active() const { return active_; }

private:
  rlimit saved_{};
  bool active_ = false;
};

}  // namespace paver::test
