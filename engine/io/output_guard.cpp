#include "io/output_guard.h"

#include "core/input_error.h"

#include <cerrno>
#include <cstring>
#include <system_error>

#include <unistd.h>

namespace paver {

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
  const auto refuse = [&](const std::string& why) {
    throw InputError("output folder " + folder.string() + ": " + why + "; choose a folder you can write to");
  };
  std::error_code ec;
  fs::path existing = fs::absolute(folder, ec);
  if (ec) refuse(ec.message());
  // The nearest part of the path that exists: the folder itself, or the parent it would be made in.
  while (!fs::exists(existing, ec)) {
    if (!existing.has_parent_path() || existing.parent_path() == existing) refuse("no part of the path exists");
    existing = existing.parent_path();
  }
  if (!fs::is_directory(existing, ec))
    refuse(existing == fs::absolute(folder, ec) ? "it is a file, not a folder"
                                                 : existing.string() + " is a file, not a folder");
  if (::access(existing.c_str(), W_OK | X_OK) != 0) refuse(existing.string() + " is not writable (" + std::strerror(errno) + ")");
}

void make_output_folder(const std::filesystem::path& folder) {
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (ec || !std::filesystem::is_directory(folder))
    throw InputError("cannot create the output folder " + folder.string() + ": " +
                     (ec ? ec.message() : "a file of that name exists"));
}

}  // namespace paver
