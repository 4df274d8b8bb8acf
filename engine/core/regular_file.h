#pragma once
// Reading a user's file without trusting its name: a pipe, a device or a folder given as a file is
// refused at once (opening a FIFO blocked forever; /dev/zero grew without bound), and no more than
// a stated number of bytes is ever read.
#include <cstdint>
#include <filesystem>
#include <string>

namespace paver {

// The whole of `path` when it is a regular file of at most `max_bytes`. Otherwise throws
// InputError "<source>: <what is wrong>; <fix>", where `kind` names the file for the user ("design
// file", "mesh file") and `if_too_large` says what to do about a file too large. Opened without blocking and checked on the open file, so a file swapped for
// a pipe after a check is still refused.
std::string read_regular_file(const std::filesystem::path& path, std::uintmax_t max_bytes, const std::string& source,
                              const std::string& kind, const std::string& if_too_large = "");

// "12.3 MiB", "512 bytes": a size for a message.
std::string byte_size_text(std::uintmax_t bytes);

}  // namespace paver
