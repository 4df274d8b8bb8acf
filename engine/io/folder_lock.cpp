#include "io/folder_lock.h"

#include "core/input_error.h"

#include <cerrno>
#include <cstring>
#include <thread>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace paver {

FolderLock::~FolderLock() {
  for (const int fd : fds_) ::close(fd);  // closing releases the lock
}

void FolderLock::lock(const std::filesystem::path& path, const std::string& shown, std::chrono::milliseconds wait) {
  const auto give_up = std::chrono::steady_clock::now() + wait;
  for (;;) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0)
      throw InputError("cannot open the output folder " + shown + " (" + std::strerror(errno) +
                       "); choose a folder you can write to");
    while (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      if (errno != EWOULDBLOCK && errno != EINTR) break;  // no locks here (some network folders): go on without
      if (std::chrono::steady_clock::now() > give_up) {
        ::close(fd);
        throw InputError("another paver run is publishing into " + shown + " and has not finished in " +
                         std::to_string(wait.count() / 1000) + " s; wait for it, or choose another output folder");
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    // The lock is on the inode: if a publish swapped another folder in while this run waited, the
    // path names that one now, and it is the one to lock.
    struct stat locked {}, now {};
    if (::fstat(fd, &locked) == 0 && ::stat(path.c_str(), &now) == 0 && locked.st_dev == now.st_dev &&
        locked.st_ino == now.st_ino) {
      fds_.push_back(fd);
      return;
    }
    ::close(fd);
    if (std::chrono::steady_clock::now() > give_up)
      throw InputError("the output folder " + shown + " keeps being replaced while this run waits to publish; "
                       "choose another output folder");
  }
}

}  // namespace paver
