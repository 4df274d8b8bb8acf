#pragma once
// An exclusive lock on a folder (flock on the folder itself), so that two runs publishing into one
// output folder take turns instead of mixing their sets. Held on the folder's inode: after a
// publish swaps a new folder in, a run that waited on the old inode sees that the path now names
// another folder and locks that one instead.
#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

namespace paver {

class FolderLock {
public:
  FolderLock() = default;
  FolderLock(FolderLock&& other) noexcept : fds_(std::move(other.fds_)) { other.fds_.clear(); }
  FolderLock& operator=(FolderLock&&) = delete;
  FolderLock(const FolderLock&) = delete;
  ~FolderLock();

  // Locks the folder at `path`, waiting up to `wait` for another run to finish; throws InputError
  // naming `shown` (the folder as the user named it) when it cannot open the folder or the wait ends.
  void lock(const std::filesystem::path& path, const std::string& shown, std::chrono::milliseconds wait);

  // The descriptor of the folder locked first (for *at() calls), -1 when none.
  int folder() const { return fds_.empty() ? -1 : fds_.front(); }

private:
  std::vector<int> fds_;
};

}  // namespace paver
