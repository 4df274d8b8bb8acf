#include "io/output_set.h"

#include "core/input_error.h"
#include "core/regular_file.h"
#include "io/atomic_file.h"
#include "io/folder_lock.h"
#include "io/output_guard.h"
#include "io/set_manifest.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string_view>
#include <system_error>

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace paver {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view kStagingTag = ".paver-staging.";
constexpr std::chrono::seconds kLockWait{30};  // a publish takes well under a second

OutputSet::TestHooks test_hooks;

// Announces a change on disk to the test hook (see output_set.h).
void step(const std::string& what) {
  if (test_hooks.step) test_hooks.step(what);
}

fs::path normal_folder(const fs::path& folder) {
  std::error_code ec;
  fs::path p = fs::absolute(folder, ec).lexically_normal();
  if (p.filename().empty() && p.has_parent_path() && p.parent_path() != p) p = p.parent_path();
  return p;
}

// Where the output folder is: a symbolic link's target (the link stays), other links on the way
// resolved too, so that the staging folder is made beside the real folder, on its filesystem.
fs::path real_folder(const fs::path& shown) {
  std::error_code ec;
  if (fs::is_symlink(fs::symlink_status(shown, ec))) {
    fs::path target = fs::canonical(shown, ec);
    if (ec)
      throw InputError("the output folder " + shown.string() + " is a symbolic link that leads nowhere (" +
                       ec.message() + "); make the folder it names, or remove the link");
    return target;
  }
  fs::path resolved = fs::weakly_canonical(shown, ec);
  return ec ? shown : resolved;
}

// An entry of a folder as lstat sees it: links are not followed.
struct Entry {
  std::string name;
  bool directory = false, regular = false;
  dev_t device = 0;
  ino_t inode = 0;
};

std::optional<Entry> entry_at(const fs::path& folder, const std::string& name) {
  struct stat s {};
  if (::lstat((folder / name).c_str(), &s) != 0) return std::nullopt;
  return Entry{name, S_ISDIR(s.st_mode), S_ISREG(s.st_mode), s.st_dev, s.st_ino};
}

std::vector<Entry> entries_of(const fs::path& folder) {
  std::vector<Entry> entries;
  DIR* dir = ::opendir(folder.c_str());
  if (!dir) return entries;
  while (const dirent* d = ::readdir(dir)) {
    const std::string name = d->d_name;
    if (name == "." || name == "..") continue;
    if (auto entry = entry_at(folder, name)) entries.push_back(std::move(*entry));
  }
  ::closedir(dir);
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) { return a.name < b.name; });
  return entries;
}

bool same_file(const Entry& a, const std::optional<Entry>& b) {
  return b && a.device == b->device && a.inode == b->inode;
}

bool same_device(const fs::path& a, const fs::path& b) {
  struct stat sa {}, sb {};
  return ::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0 && sa.st_dev == sb.st_dev;
}

bool regular_at(const fs::path& folder, const std::string& name) {
  const auto entry = entry_at(folder, name);
  return entry && entry->regular;
}

// Whether `path` is a report.json that Paver wrote: a JSON object with its design and final quality
// (every version before manifests wrote both). A user's own report.json is not.
bool is_paver_report(const fs::path& path) {
  if (!regular_at(path.parent_path(), path.filename().string())) return false;
  try {
    const nlohmann::json report =
        nlohmann::json::parse(read_regular_file(path, std::uintmax_t(64) << 20, path.string(), "report"), nullptr, false);
    return report.is_object() && report.contains("design") && report["design"].is_object() &&
           report.contains("quality_after") && report["quality_after"].is_object();
  } catch (const InputError&) {
    return false;
  }
}

// The previous set in `folder`: the regular files its manifest lists (an interrupted one-at-a-time
// publish lists the new and the old set) and the manifest; with no manifest, the known names
// beside a report.json that Paver wrote.
std::vector<std::string> previous_set(const fs::path& folder, const SetManifest& manifest,
                                      const std::vector<std::string>& known) {
  std::vector<std::string> names;
  if (manifest.found) {
    for (const auto* list : {&manifest.files, &manifest.old})
      for (const std::string& name : *list)
        if (name != kSetManifestName && !has_name(names, name) && regular_at(folder, name)) names.push_back(name);
    names.push_back(kSetManifestName);
  } else if (is_paver_report(folder / "report.json")) {
    for (const std::string& name : known)
      if (regular_at(folder, name)) names.push_back(name);
  }
  return names;
}

// A temporary file of io/atomic_file.cpp for one of `known` (".name.tmp.<pid>.<n>").
bool is_temporary_of(const std::string& entry, const std::vector<std::string>& known) {
  for (const std::string& name : known)
    if (entry.size() > name.size() + 6 && entry[0] == '.' && entry.compare(1, name.size(), name) == 0 &&
        entry.compare(1 + name.size(), 5, ".tmp.") == 0)
      return true;
  return false;
}

// "." + folder name + kStagingTag, appended piece by piece (chained operator+ trips a GCC 12
// -Wrestrict false positive).
std::string beside_prefix(const fs::path& folder) {
  std::string prefix = ".";
  prefix += folder.filename().string();
  prefix += kStagingTag;
  return prefix;
}

// The token at the end of a staging folder's name, or empty when the name is not one.
std::string staging_token(const Entry& entry, const std::string& prefix) {
  if (!entry.directory || entry.name.size() != prefix.size() + 16 || entry.name.rfind(prefix, 0) != 0) return {};
  const std::string token = entry.name.substr(prefix.size());
  return token.find_first_not_of("0123456789abcdef") == std::string::npos ? token : std::string();
}

bool process_is_gone(long pid) { return pid > 0 && ::kill(pid_t(pid), 0) != 0 && errno == ESRCH; }

void remove_or_warn(const fs::path& path, const std::string& what, std::vector<std::string>& warnings) {
  step("remove " + path.filename().string());
  if (::unlink(path.c_str()) != 0)
    warnings.push_back("could not remove " + what + " " + path.string() + " (" + std::strerror(errno) +
                       "); remove it by hand");
}

void move_or_throw(const fs::path& from, const fs::path& to) {
  step("move " + from.filename().string());
  if (::rename(from.c_str(), to.c_str()) != 0)
    throw InputError("cannot move " + from.string() + " to " + to.string() + " (" + std::strerror(errno) + ")");
}

// `warned_before`: how many warnings there were before this folder was emptied; when emptying it
// warned, the folder holds what those warnings name, otherwise something paver did not make.
void remove_folder_or_warn(const fs::path& folder, std::vector<std::string>& warnings, std::size_t warned_before) {
  step("remove folder " + folder.filename().string());
  if (::rmdir(folder.c_str()) == 0 || errno == ENOENT) return;
  warnings.push_back("left " + folder.string() +
                     (warnings.size() > warned_before ? ": it still holds what the warnings above name"
                                                      : ": it holds something paver did not make") +
                     "; look inside, then remove it");
}

// A staging folder that was never swapped in: the user's entries go back (borrowed ones moved,
// second links removed), what this or a killed run wrote there is removed, anything else stays.
void clean_unpublished(const fs::path& staging, const fs::path& folder, const std::vector<std::string>& known,
                       std::vector<std::string>& warnings) {
  const std::size_t warned_before = warnings.size();
  SetManifest marker;
  try {
    marker = read_set_manifest(staging);
  } catch (const InputError& e) {
    warnings.push_back(e.what());
    return;
  }
  for (const Entry& entry : entries_of(staging)) {
    if (entry.name == kSetManifestName) continue;
    const auto home = entry_at(folder, entry.name);
    if (has_name(marker.borrowed, entry.name) && !home) {
      move_or_throw(staging / entry.name, folder / entry.name);
    } else if (same_file(entry, home)) {
      remove_or_warn(staging / entry.name, "a second link of", warnings);
    } else if (entry.regular && (has_name(known, entry.name) || is_temporary_of(entry.name, known) ||
                                 is_temporary_of(entry.name, {kSetManifestName}))) {
      remove_or_warn(staging / entry.name, "the unpublished", warnings);
    } else {
      warnings.push_back("left " + (staging / entry.name).string() + " in place: paver did not make it");
    }
  }
  if (regular_at(staging, kSetManifestName)) remove_or_warn(staging / kSetManifestName, "the staging marker", warnings);
  remove_folder_or_warn(staging, warnings, warned_before);
}

// The previous folder, swapped out to `old` by a publish: its set is removed, the second links of the
// user's files too, what appeared in it meanwhile goes back, anything else stays. The proof of the
// set (report.json when there is no manifest, else the manifest) is removed last, so that a kill
// midway leaves a folder a later run can still prove ours.
void clean_swapped_out(const fs::path& old, const fs::path& folder, const std::vector<std::string>& known,
                       std::vector<std::string>& warnings) {
  const std::size_t warned_before = warnings.size();
  std::vector<std::string> previous;
  try {
    previous = previous_set(old, read_set_manifest(old), known);
  } catch (const InputError& e) {
    warnings.push_back(e.what());
  }
  std::vector<std::string> proofs;
  for (const Entry& entry : entries_of(old)) {
    const auto home = entry_at(folder, entry.name);
    if (same_file(entry, home)) remove_or_warn(old / entry.name, "a second link of", warnings);
    else if (entry.name == "report.json" || entry.name == kSetManifestName) proofs.push_back(entry.name);
    else if (entry.regular && has_name(previous, entry.name)) remove_or_warn(old / entry.name, "the previous set's", warnings);
    else if (!home) move_or_throw(old / entry.name, folder / entry.name);
    else warnings.push_back("left " + (old / entry.name).string() + ": " + folder.string() + " has an entry of that name");
  }
  for (const char* proof : {"report.json", kSetManifestName}) {
    const std::string name = proof;
    if (!has_name(proofs, name)) continue;
    if (has_name(previous, name)) remove_or_warn(old / name, "the previous set's", warnings);
    else if (!entry_at(folder, name)) move_or_throw(old / name, folder / name);
    else warnings.push_back("left " + (old / name).string() + ": paver did not make it");
  }
  remove_folder_or_warn(old, warnings, warned_before);
}

void write_manifest(const fs::path& folder, const SetManifest& manifest) {
  step("write manifest in " + folder.filename().string());
  write_text_atomically(folder / kSetManifestName, set_manifest_text(manifest));
}

// The end of a publish one file at a time, from `staging` inside `folder` whose manifest (`manifest`)
// names the new set and the old: the new files but `last` moved in, the old set's others removed,
// the manifest made the new set's alone, `last` moved in, the staging folder removed. A run that
// finds such a publish interrupted ends it so.
void finish_moves(const fs::path& folder, const fs::path& staging, SetManifest manifest, const std::string& last,
                  const std::vector<std::string>& known, std::vector<std::string>& warnings) {
  for (const std::string& name : manifest.files)
    if (name != last && regular_at(staging, name)) move_or_throw(staging / name, folder / name);
  for (const std::string& name : manifest.old)
    if (!has_name(manifest.files, name) && regular_at(folder, name))
      remove_or_warn(folder / name, "the previous set's", warnings);
  manifest.old.clear();
  write_manifest(folder, manifest);
  if (regular_at(staging, last)) move_or_throw(staging / last, folder / last);
  clean_unpublished(staging, folder, known, warnings);
}

int recover_locked(const fs::path& folder, const std::vector<std::string>& known, std::vector<std::string>& warnings) {
  const SetManifest published = read_set_manifest(folder);
  const auto is_killed_staging = [](const fs::path& staging, const std::string& token) {
    try {
      const SetManifest marker = read_set_manifest(staging);
      return marker.token == token && process_is_gone(marker.pid);
    } catch (const InputError&) {
      return false;  // not a marker of ours
    }
  };
  int dealt_with = 0;
  const std::string beside = beside_prefix(folder);
  for (const Entry& entry : entries_of(folder.parent_path())) {
    const std::string token = staging_token(entry, beside);
    if (token.empty()) continue;
    const fs::path staging = folder.parent_path() / entry.name;
    if (published.found && published.token == token) clean_swapped_out(staging, folder, known, warnings);
    else if (is_killed_staging(staging, token)) clean_unpublished(staging, folder, known, warnings);
    else continue;
    ++dealt_with;
  }
  for (const Entry& entry : entries_of(folder)) {
    if (entry.regular && is_temporary_of(entry.name, {kSetManifestName}) &&
        process_is_gone(std::atol(entry.name.c_str() + std::strlen(kSetManifestName) + 6)))
      remove_or_warn(folder / entry.name, "a killed run's temporary", warnings);  // ".paver-files.tmp.<pid>.<n>"
    const std::string token = staging_token(entry, std::string(kStagingTag));
    if (token.empty()) continue;
    const fs::path staging = folder / entry.name;
    if (published.found && published.token == token) finish_moves(folder, staging, published, "report.json", known, warnings);
    else if (is_killed_staging(staging, token)) clean_unpublished(staging, folder, known, warnings);
    else continue;
    ++dealt_with;
  }
  return dealt_with;
}

}  // namespace

void OutputSet::set_test_hooks(TestHooks hooks) { test_hooks = hooks; }

OutputSet::OutputSet(fs::path folder, std::vector<std::string> known_names)
    : shown_(normal_folder(folder)), folder_(real_folder(shown_)), token_(random_token()), known_(std::move(known_names)) {
  std::error_code ec;
  const fs::path parent = folder_.parent_path();
  const bool exists = fs::is_directory(folder_, ec);
  if (!exists) fs::create_directories(parent, ec);
  // Beside the folder, so that it can become or swap with it; inside it when its parent is not ours
  // to write or is another filesystem (then the files are moved in one at a time).
  beside_ = parent != folder_ && (!exists || same_device(folder_, parent)) && !test_hooks.one_at_a_time;
  if (beside_) {
    staging_ = parent / (beside_prefix(folder_) + token_);
    beside_ = ::mkdir(staging_.c_str(), 0777) == 0;
  }
  if (!beside_) {
    make_output_folder(folder_);
    std::string inside(kStagingTag);
    inside += token_;
    staging_ = folder_ / inside;
    if (::mkdir(staging_.c_str(), 0777) != 0)
      throw InputError("cannot write in the output folder " + shown_.string() + " (" + std::strerror(errno) +
                       "); choose a folder you can write to");
  }
  // The marker: a staging folder left by a kill is known for ours by it, and by nothing else.
  SetManifest marker;
  marker.token = token_;
  marker.pid = long(::getpid());
  write_text_atomically(staging_ / kSetManifestName, set_manifest_text(marker));
}

OutputSet::~OutputSet() {
  if (published_) return;
  try {
    std::vector<std::string> ignored;
    clean_unpublished(staging_, folder_, known_, ignored);
  } catch (...) {
    // A destructor must not throw; what could not be cleaned is proven ours and a later run removes it.
  }
}

void OutputSet::publish(const std::string& last) {
  std::vector<std::string> staged;
  for (const Entry& entry : entries_of(staging_))
    if (entry.name != kSetManifestName) staged.push_back(entry.name);
  SetManifest manifest;
  manifest.token = token_;
  manifest.pid = long(::getpid());
  manifest.files = staged;
  std::error_code ec;
  if (beside_ && !fs::exists(fs::symlink_status(folder_, ec))) {
    write_manifest(staging_, manifest);
    step("rename into place");
    if (::rename(staging_.c_str(), folder_.c_str()) == 0) {
      published_ = true;
      return;
    }  // made meanwhile by another run: publish into it as into any folder
  }
  FolderLock lock;
  lock.lock(folder_, shown_.string(), kLockWait);
  try {
    recover_locked(folder_, known_, warnings_);
    if (beside_) publish_by_exchange(staged);
    if (!published_) publish_one_by_one(staged, last);
  } catch (...) {
    if (!published_) clean_unpublished(staging_, folder_, known_, warnings_);
    throw;
  }
}

void OutputSet::publish_by_exchange(const std::vector<std::string>& staged) {
  const SetManifest published = read_set_manifest(folder_);
  const std::vector<std::string> previous = previous_set(folder_, published, known_);
  std::vector<Entry> users;
  for (const Entry& entry : entries_of(folder_)) {
    if (has_name(previous, entry.name)) continue;
    if (has_name(staged, entry.name))
      throw InputError((shown_ / entry.name).string() + ": appeared during the run and paver did not write it; move it "
                       "away and run again (" + shown_.string() + " is left as it was)");
    users.push_back(entry);
  }
  // The user's entries join the new folder: files as second links (never absent from the folder),
  // folders and what cannot be linked moved, after the manifest records them for a recovery.
  SetManifest manifest = read_set_manifest(staging_);
  manifest.files = staged;
  for (const Entry& entry : users) {
    step("link " + entry.name);
    if (entry.directory || ::link((folder_ / entry.name).c_str(), (staging_ / entry.name).c_str()) != 0)
      manifest.borrowed.push_back(entry.name);
  }
  write_manifest(staging_, manifest);
  for (const std::string& name : manifest.borrowed) move_or_throw(folder_ / name, staging_ / name);
  FolderLock staged_lock;  // the new folder's inode: a run that opens it after the swap waits for the cleaning
  staged_lock.lock(staging_, shown_.string(), kLockWait);
  step("exchange");
  if (::renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, folder_.c_str(), RENAME_EXCHANGE) == 0) {
    published_ = true;
    clean_swapped_out(staging_, folder_, known_, warnings_);
    return;
  }
  const int error = errno;
  if (error != EINVAL && error != ENOSYS && error != ENOTSUP && error != EXDEV)
    throw InputError("cannot publish into " + shown_.string() + " (" + std::strerror(error) + "); it is left as it was");
  // This filesystem cannot swap folders: the user's entries go back, and the files go in one at a time.
  for (const std::string& name : manifest.borrowed) move_or_throw(staging_ / name, folder_ / name);
  for (const Entry& entry : users)
    if (!has_name(manifest.borrowed, entry.name)) remove_or_warn(staging_ / entry.name, "a second link of", warnings_);
  manifest.borrowed.clear();
  write_manifest(staging_, manifest);
  const fs::path inside = folder_ / (std::string(kStagingTag) + token_);
  move_or_throw(staging_, inside);
  staging_ = inside;
  beside_ = false;
}

void OutputSet::publish_one_by_one(const std::vector<std::string>& staged, const std::string& last) {
  const SetManifest published = read_set_manifest(folder_);
  std::vector<std::string> previous = previous_set(folder_, published, known_);
  for (const std::string& name : staged)
    if (entry_at(folder_, name) && !has_name(previous, name))
      throw InputError((shown_ / name).string() + ": appeared during the run and paver did not write it; move it "
                       "away and run again (" + shown_.string() + " is left as it was)");
  SetManifest manifest;
  manifest.token = token_;
  manifest.pid = long(::getpid());
  manifest.files = staged;
  std::erase(previous, std::string(kSetManifestName));
  manifest.old = previous;
  // From here every file in the folder is proven ours by the manifest, old or new, until the end.
  write_manifest(folder_, manifest);
  published_ = true;
  finish_moves(folder_, staging_, manifest, last, known_, warnings_);
}

void OutputSet::refuse_replacing_users_files(const fs::path& folder, const std::vector<fs::path>& outputs,
                                             const std::vector<std::string>& known_names) {
  const fs::path f = real_folder(normal_folder(folder));
  std::error_code ec;
  if (!fs::is_directory(f, ec)) return;
  const std::vector<std::string> previous = previous_set(f, read_set_manifest(f), known_names);
  for (const fs::path& output : outputs) {
    const std::string name = output.filename().string();
    if (entry_at(f, name) && !has_name(previous, name))
      throw InputError((normal_folder(folder) / name).string() +
                       ": exists and no earlier paver run wrote it; move it away or choose another output folder");
  }
}

int OutputSet::recover_interrupted(const fs::path& folder, const std::vector<std::string>& known_names) {
  const fs::path shown = normal_folder(folder);
  const fs::path real = real_folder(shown);
  std::error_code ec;
  if (!fs::is_directory(real, ec)) return 0;
  FolderLock lock;
  lock.lock(real, shown.string(), kLockWait);
  std::vector<std::string> warnings;
  return recover_locked(real, known_names, warnings);
}

std::string OutputSet::with_final_names(std::string message) const {
  const std::string staged = staging_.string(), final_folder = shown_.string();
  for (std::size_t at = message.find(staged); at != std::string::npos; at = message.find(staged, at + final_folder.size()))
    message.replace(at, staged.size(), final_folder);
  return message;
}

}  // namespace paver
