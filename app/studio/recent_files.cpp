#include "recent_files.h"

#include "io/atomic_file.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <string>
#include <system_error>

namespace paver::studio {

namespace fs = std::filesystem;

fs::path recent_files_path() {
  if (const char* config = std::getenv("XDG_CONFIG_HOME"); config && *config) return fs::path(config) / "paver/recent.txt";
  if (const char* home = std::getenv("HOME"); home && *home) return fs::path(home) / ".config/paver/recent.txt";
  return {};
}

std::vector<fs::path> load_recent_files(const fs::path& file) {
  std::vector<fs::path> recent;
  if (file.empty()) return recent;
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line))
    if (!line.empty()) recent.emplace_back(line);
  return recent;
}

void remember_recent_file(std::vector<fs::path>& recent, const fs::path& opened, std::size_t limit) {
  std::error_code ec;
  fs::path absolute = fs::absolute(opened, ec).lexically_normal();
  if (ec) absolute = opened;
  std::erase(recent, absolute);
  recent.insert(recent.begin(), absolute);
  if (recent.size() > limit) recent.resize(limit);
}

void save_recent_files(const fs::path& file, const std::vector<fs::path>& recent) {
  if (file.empty()) return;
  std::error_code ec;
  fs::create_directories(file.parent_path(), ec);  // a failure shows in the write's error
  std::string text;
  for (const auto& path : recent) text += path.string() + "\n";
  write_text_atomically(file, text);
}

}  // namespace paver::studio
