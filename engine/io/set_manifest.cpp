#include "io/set_manifest.h"

#include "core/input_error.h"
#include "core/regular_file.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <random>
#include <sstream>
#include <string_view>
#include <system_error>

namespace paver {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view kHeader = "# paver output set;";

// The value after `key` in the header line ("token=" -> the digits), empty when absent.
std::string header_value(std::string_view header, std::string_view key) {
  const std::size_t at = header.find(key);
  if (at == std::string_view::npos) return {};
  const std::size_t from = at + key.size();
  return std::string(header.substr(from, header.find(' ', from) - from));
}

// A name on one line: a user's entry may have a newline or a backslash in its name (a name that
// read back as two lines could make a user's file look like one of ours).
std::string name_escaped(const std::string& name) {
  std::string out;
  for (const char c : name) {
    if (c == '\\') out += "\\\\";
    else if (c == '\n') out += "\\n";
    else out += c;
  }
  return out;
}

std::string name_unescaped(std::string_view text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\\' && i + 1 < text.size()) {
      ++i;
      out += text[i] == 'n' ? '\n' : text[i];
    } else {
      out += text[i];
    }
  }
  return out;
}

}  // namespace

bool has_name(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

std::string random_token() {
  std::random_device source;
  std::uniform_int_distribution<std::uint64_t> digits;
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(digits(source)));
  return text;
}

SetManifest read_set_manifest(const fs::path& folder) {
  SetManifest manifest;
  const fs::path path = folder / kSetManifestName;
  std::error_code ec;
  const fs::file_status status = fs::symlink_status(path, ec);
  if (!fs::exists(status)) return manifest;
  if (!fs::is_regular_file(status))
    throw InputError(path.string() + ": is not a regular file but " +
                     (fs::is_directory(status) ? "a folder" : fs::is_symlink(status) ? "a symbolic link" : "a special file") +
                     "; Paver keeps the list of the files it wrote there: move it away or choose another output folder");
  const std::string text = read_regular_file(path, std::uintmax_t(1) << 20, path.string(), "manifest of paver's files",
                                             "move it away or choose another output folder");
  manifest.found = true;
  std::istringstream lines(text);
  std::string line;
  const bool tokened = std::getline(lines, line) && line.rfind(kHeader, 0) == 0;
  if (tokened) {
    manifest.token = header_value(line, "token=");
    const std::string pid = header_value(line, "pid=");
    if (!pid.empty() && pid.size() < 12 && pid.find_first_not_of("0123456789") == std::string::npos)
      manifest.pid = std::stol(pid);
  } else {
    lines.clear();
    lines.seekg(0);
  }
  while (std::getline(lines, line)) {
    if (line.empty()) continue;
    const std::string_view text_line = line;
    if (!tokened) manifest.files.push_back(line);
    else if (line.rfind("file ", 0) == 0) manifest.files.push_back(name_unescaped(text_line.substr(5)));
    else if (line.rfind("old ", 0) == 0) manifest.old.push_back(name_unescaped(text_line.substr(4)));
    else if (line.rfind("borrowed ", 0) == 0) manifest.borrowed.push_back(name_unescaped(text_line.substr(9)));
  }
  return manifest;
}

std::string set_manifest_text(const SetManifest& manifest) {
  std::string text(kHeader);
  text += " token=" + manifest.token + " pid=" + std::to_string(manifest.pid) + "\n";
  for (const std::string& name : manifest.files) text += "file " + name_escaped(name) + "\n";
  for (const std::string& name : manifest.old) text += "old " + name_escaped(name) + "\n";
  for (const std::string& name : manifest.borrowed) text += "borrowed " + name_escaped(name) + "\n";
  return text;
}

}  // namespace paver
