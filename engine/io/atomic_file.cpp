#include "io/atomic_file.h"

#include "core/input_error.h"
#include "io/output_guard.h"

#include <atomic>
#include <cerrno>
#include <fstream>
#include <string>
#include <system_error>

#ifdef _WIN32
#include <process.h>
#else
#include <unistd.h>
#endif

namespace paver {
namespace {

long process_id() {
#ifdef _WIN32
  return static_cast<long>(_getpid());
#else
  return static_cast<long>(getpid());
#endif
}

// The pid keeps two processes writing the same target apart; the counter keeps two threads (or
// two calls) of one process apart.
std::filesystem::path temporary_path_beside(const std::filesystem::path& path) {
  static std::atomic<unsigned long> counter{0};
  // Appending piece by piece sidesteps a GCC 12 -Wrestrict false positive on chained operator+.
  std::string name = ".";
  name += path.filename().string();
  name += ".tmp.";
  name += std::to_string(process_id());
  name += '.';
  name += std::to_string(counter.fetch_add(1));
  return path.parent_path() / name;
}

std::filesystem::path folder_of(const std::filesystem::path& path) {
  return path.parent_path().empty() ? std::filesystem::path(".") : path.parent_path();
}

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& reason) {
  throw InputError("cannot write " + path.string() + ": " + reason);
}

// Best effort: the temporary file may not exist (open failed) and a failure to remove it must not
// hide the error that brought us here.
void remove_quietly(const std::filesystem::path& path) {
  std::error_code ignored;
  std::filesystem::remove(path, ignored);
}

}  // namespace

void write_file_atomically_by_name(const std::filesystem::path& path,
                                   const std::function<void(const std::filesystem::path& temporary)>& write) {
  check_output_file(path);
  std::error_code ec;
  const std::filesystem::path temporary = temporary_path_beside(path);
  try {
    write(temporary);
  } catch (...) {
    remove_quietly(temporary);
    throw;
  }
  if (!std::filesystem::is_regular_file(temporary, ec)) {
    remove_quietly(temporary);
    fail(path, "the writer left no file (is the folder writable?)");
  }
  std::filesystem::rename(temporary, path, ec);
  if (ec) {
    remove_quietly(temporary);
    fail(path, "cannot replace the file: " + ec.message());
  }
}

void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write) {
  write_file_atomically_by_name(path, [&](const std::filesystem::path& temporary) {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out.is_open()) fail(path, "the folder " + folder_of(path).string() + " is not writable");
    errno = 0;
    write(out);
    // A full disk or an I/O error only shows in the stream state, often not before flush or close.
    out.flush();
    const bool written = static_cast<bool>(out);
    out.close();
    if (!written || out.fail()) {
      const int error = errno;
      fail(path, error == EFBIG    ? "writing failed: the file is larger than this process may write (ulimit -f)"
                 : error == ENOSPC ? "writing failed: the disk is full"
                                   : "writing failed (is the disk full?)");
    }
  });
}

void write_text_atomically(const std::filesystem::path& path, std::string_view text) {
  write_file_atomically(path, [text](std::ostream& out) {
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
  });
}

}  // namespace paver
