#pragma once
// Writes files so that a reader never sees a half-written one and nothing a user wrote is lost:
// the content goes to a temporary file beside the target, which is then renamed over it.
#include <filesystem>
#include <functional>
#include <ostream>
#include <string_view>

namespace paver {

// Calls `write` with a binary stream on a temporary file, then renames it to `path`.
// Throws InputError naming the path when the folder is not writable or the write fails.
void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write);

// The same for a library that writes only to a file name of its own: `write` is given the
// temporary path to create, which is renamed to `path` once it returns.
void write_file_atomically_by_name(const std::filesystem::path& path,
                                   const std::function<void(const std::filesystem::path& temporary)>& write);

void write_text_atomically(const std::filesystem::path& path, std::string_view text);

}  // namespace paver
