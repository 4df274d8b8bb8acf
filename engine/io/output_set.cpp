#include "io/output_set.h"

#include "core/input_error.h"
#include "io/output_guard.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <cstdint>
#include <fstream>
#include <string_view>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

namespace paver {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view kStagingTag = ".paver-staging.";
constexpr const char* kManifest = ".paver-files";

fs::path normal_folder(const fs::path& folder) {
  std::error_code ec;
  fs::path p = fs::absolute(folder, ec).lexically_normal();
  if (p.filename().empty() && p.has_parent_path() && p.parent_path() != p) p = p.parent_path();
  return p;
}

bool listed(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

// Whether `path` is a report.json that Paver wrote: a JSON object with its design and final quality
// (every version before manifests wrote both). A user's own report.json, or any other file of that
// name, is not: it made every file with an output's name count as an old run's.
bool is_paver_report(const fs::path& path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec) || fs::file_size(path, ec) > (std::uintmax_t(64) << 20)) return false;
  std::ifstream in(path, std::ios::binary);
  const nlohmann::json report = nlohmann::json::parse(in, nullptr, false);
  return report.is_object() && report.contains("design") && report["design"].is_object() &&
         report.contains("quality_after") && report["quality_after"].is_object();
}

// The files of `folder` that an earlier run published there (see output_set.h), among `known`.
std::vector<std::string> previous_run_files(const fs::path& folder, const std::vector<std::string>& known) {
  std::vector<std::string> files;
  std::error_code ec;
  std::ifstream manifest(folder / kManifest);
  if (manifest) {
    for (std::string name; std::getline(manifest, name);)
      if (listed(known, name) && fs::exists(folder / name, ec)) files.push_back(name);
    return files;
  }
  if (!is_paver_report(folder / "report.json")) return files;
  for (const std::string& name : known)
    if (fs::exists(folder / name, ec)) files.push_back(name);
  return files;
}

bool contains_only(const fs::path& folder, const std::vector<std::string>& names) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    const std::string name = entry.path().filename().string();
    if (std::find(names.begin(), names.end(), name) == names.end()) return false;
  }
  return !ec;
}

// rename(2), or copy and remove across filesystems.
void move_file(const fs::path& from, const fs::path& to) {
  std::error_code ec;
  fs::rename(from, to, ec);
  if (ec == std::errc::cross_device_link) {
    fs::copy_file(from, to, fs::copy_options::overwrite_existing, ec);
    if (!ec) fs::remove(from, ec);
  }
  if (ec) throw InputError("cannot move " + from.string() + " to " + to.string() + ": " + ec.message());
}

// "." + folder name + kStagingTag, appended piece by piece (chained operator+ trips a GCC 12
// -Wrestrict false positive).
std::string beside_prefix(const fs::path& folder) {
  std::string prefix = ".";
  prefix += folder.filename().string();
  prefix += kStagingTag;
  return prefix;
}

bool process_is_gone(long pid) { return pid > 0 && ::kill(pid_t(pid), 0) != 0 && errno == ESRCH; }

// Removes the entries of `folder` named `prefix`<pid> whose process is gone.
int remove_stale(const fs::path& folder, const std::string& prefix) {
  int removed = 0;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(prefix, 0) != 0) continue;
    const std::string digits = name.substr(prefix.size());
    if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos) continue;
    if (!process_is_gone(std::stol(digits))) continue;
    std::error_code ignored;
    fs::remove_all(entry.path(), ignored);
    ++removed;
  }
  return removed;
}

}  // namespace

OutputSet::OutputSet(fs::path folder, std::vector<std::string> known_names)
    : folder_(normal_folder(folder)), known_(std::move(known_names)), previous_(previous_run_files(folder_, known_)) {
  previous_.push_back(kManifest);
  const std::string pid = std::to_string(long(::getpid()));
  std::error_code ec;
  fs::create_directories(folder_.parent_path(), ec);
  // Beside the folder, so that it can become or swap with it; inside it when its parent is not ours
  // to write (then the files are moved in one by one).
  staging_ = folder_.parent_path() / (beside_prefix(folder_) + pid);
  fs::remove_all(staging_, ec);
  if (folder_.has_parent_path() && folder_.parent_path() != folder_ && fs::create_directory(staging_, ec) && !ec)
    return;
  make_output_folder(folder_);
  std::string inside(kStagingTag);
  inside += pid;
  staging_ = folder_ / inside;
  fs::remove_all(staging_, ec);
  if (!fs::create_directory(staging_, ec) || ec)
    throw InputError("cannot write in the output folder " + folder_.string() + ": " + ec.message());
}

OutputSet::~OutputSet() {
  if (published_) return;
  std::error_code ignored;
  fs::remove_all(staging_, ignored);
}

void OutputSet::publish(const std::string& last) {
  std::error_code ec;
  // The staged files, listed once: the manifest names them, the one-by-one path moves them.
  std::vector<std::string> staged;
  for (const auto& entry : fs::directory_iterator(staging_)) staged.push_back(entry.path().filename().string());
  std::sort(staged.begin(), staged.end());
  {
    std::ofstream manifest(staging_ / kManifest);
    for (const std::string& name : staged) manifest << name << "\n";
    if (!manifest.flush()) throw InputError("cannot write " + (staging_ / kManifest).string());
  }
  const bool beside = staging_.parent_path() == folder_.parent_path();
  if (beside && !fs::exists(folder_, ec)) {
    fs::rename(staging_, folder_, ec);
    if (!ec) {
      published_ = true;
      return;
    }
  }
  if (beside && contains_only(folder_, previous_) &&
      ::renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, folder_.c_str(), RENAME_EXCHANGE) == 0) {
    published_ = true;
    fs::remove_all(staging_, ec);  // the previous run's set, swapped out
    return;
  }
  // One by one: everything but `last`, then the previous run's files this run did not write, then
  // the manifest, then `last`.
  for (const std::string& name : staged)
    if (name != last) move_file(staging_ / name, folder_ / name);
  for (const std::string& name : previous_)
    if (!listed(staged, name)) fs::remove(folder_ / name, ec);
  move_file(staging_ / kManifest, folder_ / kManifest);
  if (listed(staged, last)) move_file(staging_ / last, folder_ / last);
  published_ = true;
  fs::remove_all(staging_, ec);
}

void OutputSet::refuse_replacing_users_files(const fs::path& folder, const std::vector<fs::path>& outputs,
                                             const std::vector<std::string>& known_names) {
  const fs::path f = normal_folder(folder);
  std::error_code ec;
  if (!fs::is_directory(f, ec)) return;
  const std::vector<std::string> previous = previous_run_files(f, known_names);
  for (const fs::path& output : outputs) {
    const std::string name = output.filename().string();
    if (fs::exists(f / name, ec) && !listed(previous, name))
      throw InputError((f / name).string() + ": exists and no earlier paver run wrote it; move it away or choose another output folder");
  }
}

int OutputSet::remove_stale_staging(const fs::path& folder) {
  const fs::path f = normal_folder(folder);
  int removed = remove_stale(f.parent_path(), beside_prefix(f));
  std::error_code ec;
  if (fs::is_directory(f, ec)) removed += remove_stale(f, std::string(kStagingTag));
  return removed;
}

std::string OutputSet::with_final_names(std::string message) const {
  const std::string staged = staging_.string(), final_folder = folder_.string();
  for (std::size_t at = message.find(staged); at != std::string::npos; at = message.find(staged, at + final_folder.size()))
    message.replace(at, staged.size(), final_folder);
  return message;
}

}  // namespace paver
