#include "io/output_guard.h"

#include "core/input_error.h"
#include "core/printable.h"

#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>

#include <unistd.h>

namespace paver {
namespace {

constexpr std::size_t kMaxNameBytes = 255;    // NAME_MAX on Linux file systems
constexpr std::size_t kMaxPathBytes = 4095;   // PATH_MAX less its terminating NUL
constexpr std::size_t kRoomForOutputNames = 64;  // "/.paver-staging.<16 digits>/..elements.glb.tmp.<pid>.<n>"

}  // namespace

void refuse_overwriting_inputs(const std::vector<std::filesystem::path>& inputs,
                               const std::vector<std::filesystem::path>& outputs) {
  for (const auto& out : outputs) {
    std::error_code ec;
    if (!std::filesystem::exists(out, ec)) continue;
    for (const auto& in : inputs) {
      if (in.empty()) continue;
      if (std::filesystem::equivalent(in, out, ec))
        throw InputError("refusing to write " + out.string() + ": it is the input " + in.string() +
                         "; write the output elsewhere");
    }
  }
}

void check_output_folder(const std::filesystem::path& folder) {
  namespace fs = std::filesystem;
  const auto refuse = [&](const std::string& why, const std::string& fix = "choose a folder you can write to") {
    throw InputError("output folder " + printable_cut(folder.string()) + ": " + why + "; " + fix);
  };
  std::error_code ec;
  const fs::path absolute = fs::absolute(folder, ec);
  if (ec) refuse(ec.message());
  // A name or a path too long fails every write after the work: refuse it now. The room kept is for
  // the longest name a run writes in the folder and the staging folder made beside it.
  for (const fs::path& part : absolute)
    if (part.native().size() > kMaxNameBytes)
      refuse("the name '" + printable(part.native().substr(0, 40)) + "...' is " + std::to_string(part.native().size()) +
                 " bytes long, more than the " + std::to_string(kMaxNameBytes) + " a file system allows",
             "choose a shorter name");
  if (absolute.native().size() + kRoomForOutputNames > kMaxPathBytes)
    refuse("the path is " + std::to_string(absolute.native().size()) + " bytes long; with the files written in it, " +
               "it would pass the " + std::to_string(kMaxPathBytes) + " bytes a path may have",
           "choose a shorter path");
  const fs::file_status link = fs::symlink_status(absolute, ec);
  if (fs::is_symlink(link)) {
    (void)fs::status(absolute, ec);
    if (ec) refuse("it is a symbolic link that leads nowhere (" + ec.message() + ")", "make the folder it names, or remove the link");
  }
  // The nearest part of the path that exists: the folder itself, or the parent it would be made in.
  // An error other than "not there" (a symbolic link loop, a part that is a file) is the answer.
  fs::path existing = absolute;
  while (!fs::exists(existing, ec)) {
    if (ec && ec != std::errc::no_such_file_or_directory && ec != std::errc::not_a_directory) refuse(printable_cut(existing.string()) + ": " + ec.message());
    if (!existing.has_parent_path() || existing.parent_path() == existing) refuse("no part of the path exists");
    existing = existing.parent_path();
  }
  if (!fs::is_directory(existing, ec))
    refuse(existing == absolute ? "it is a file, not a folder" : existing.string() + " is a file, not a folder");
  if (::access(existing.c_str(), W_OK | X_OK) != 0) refuse(existing.string() + " is not writable (" + std::strerror(errno) + ")");
}

void check_output_file(const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  const auto refuse = [&](const std::string& why, const std::string& what_to_do) {
    throw InputError("cannot write " + path.string() + ": " + why + "; " + what_to_do);
  };
  if (path.filename().empty() || path.filename() == "." || path.filename() == "..")
    refuse("the path names a folder, not a file", "give the file's name");
  std::error_code ec;
  const fs::file_status status = fs::symlink_status(path, ec);
  if (fs::exists(status)) {
    if (fs::is_symlink(status)) refuse("it is a symbolic link", "write to the file it points to, or choose another name");
    if (fs::is_directory(status)) refuse("it is a folder", "give a file's name");
    if (!fs::is_regular_file(status))
      refuse("it is not a regular file (a device, a pipe or a socket)", "choose another name");
  }
  const fs::path folder = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  if (!fs::is_directory(folder, ec)) refuse("the folder " + folder.string() + " does not exist", "create it first");
  if (::access(folder.c_str(), W_OK | X_OK) != 0)
    refuse("the folder " + folder.string() + " is not writable (" + std::strerror(errno) + ")", "choose another folder");
}

void make_output_folder(const std::filesystem::path& folder) {
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (ec || !std::filesystem::is_directory(folder))
    throw InputError("cannot create the output folder " + folder.string() + ": " +
                     (ec ? ec.message() : "a file of that name exists"));
}

}  // namespace paver
