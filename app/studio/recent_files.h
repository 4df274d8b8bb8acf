#pragma once
// The surfaces and designs opened lately, newest first, kept in $XDG_CONFIG_HOME/paver/recent.txt
// (default ~/.config/paver/recent.txt), one absolute path per line, written atomically.
#include <filesystem>
#include <vector>

namespace paver::studio {

// The file the list lives in; empty when neither $XDG_CONFIG_HOME nor $HOME is set.
std::filesystem::path recent_files_path();

// The list as stored; empty when there is none yet. Never throws.
std::vector<std::filesystem::path> load_recent_files(const std::filesystem::path& file);

// Moves `opened` to the front (made absolute), keeps at most `limit` entries.
void remember_recent_file(std::vector<std::filesystem::path>& recent, const std::filesystem::path& opened,
                          std::size_t limit = 12);

// Throws InputError naming the file when it cannot be written.
void save_recent_files(const std::filesystem::path& file, const std::vector<std::filesystem::path>& recent);

}  // namespace paver::studio
