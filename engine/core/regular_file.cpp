#include "core/regular_file.h"

#include "core/input_error.h"

#include <cerrno>
#include <cstdio>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace paver {
namespace {

// Closes the descriptor whatever way the read ends.
struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

const char* kind_of(mode_t mode) {
  if (S_ISFIFO(mode)) return "a pipe";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
  if (S_ISSOCK(mode)) return "a socket";
  return "an unknown kind of file";
}

}  // namespace

std::string byte_size_text(std::uintmax_t bytes) {
  if (bytes < 1024) return std::to_string(bytes) + " bytes";
  char text[32];
  const double mib = double(bytes) / double(1 << 20);
  if (mib < 1) std::snprintf(text, sizeof text, "%.1f KiB", double(bytes) / 1024);
  else if (mib < 1024) std::snprintf(text, sizeof text, "%.1f MiB", mib);
  else std::snprintf(text, sizeof text, "%.1f GiB", mib / 1024);
  return text;
}

std::string read_regular_file(const std::filesystem::path& path, std::uintmax_t max_bytes, const std::string& source,
                              const std::string& kind, const std::string& if_too_large) {
  const auto fail = [&](const std::string& what) -> void { throw InputError(source + ": " + what); };
  const Descriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY)};
  if (file.fd < 0) {
    const int error = errno;
    if (error == ENOENT) fail("no such " + kind + " (file not found); check the path");
    if (error == EACCES) fail("cannot open the " + kind + " for reading (permission denied); check its permissions");
    fail("cannot open the " + kind + " (" + std::strerror(error) + ")");
  }
  struct stat status {};
  if (::fstat(file.fd, &status) != 0) fail("cannot read the " + kind + " (" + std::strerror(errno) + ")");
  if (S_ISDIR(status.st_mode)) fail("is a folder, not a " + kind + "; give the file's path");
  if (!S_ISREG(status.st_mode))
    fail(std::string("is not a regular file (") + kind_of(status.st_mode) + "); save the " + kind +
         " to a file and give that file's path");
  const auto size = std::uintmax_t(status.st_size);
  if (size > max_bytes)
    fail("the file is too large (" + std::to_string(size) + " bytes); Paver reads " + kind + "s of up to " +
         byte_size_text(max_bytes) + (if_too_large.empty() ? "" : ": " + if_too_large));
  std::string bytes(size, '\0');
  std::size_t done = 0;
  while (done < size) {
    const ssize_t got = ::read(file.fd, bytes.data() + done, size - done);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) break;
    done += std::size_t(got);
  }
  // One byte more tells a file that grew while being read; it is read again by the user, not guessed at.
  char extra = 0;
  if (done != size || ::read(file.fd, &extra, 1) != 0)
    fail("could not be read (an I/O error, or the file changed while being read); try again");
  return bytes;
}

}  // namespace paver
