#include "io/output_guard.h"

#include "core/input_error.h"

#include <system_error>

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
                         "; choose another output folder");
    }
  }
}

void make_output_folder(const std::filesystem::path& folder) {
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (ec || !std::filesystem::is_directory(folder))
    throw InputError("cannot create the output folder " + folder.string() + ": " +
                     (ec ? ec.message() : "a file of that name exists"));
}

}  // namespace paver
