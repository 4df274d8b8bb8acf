#pragma once
// A problem with something the user gave us (a file, a flag, a design). The CLI prints what()
// and exits with code 2; the editor shows it. Messages name the file, the place and the fix.
#include <stdexcept>
#include <string>

namespace paver {

class InputError : public std::runtime_error {
public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace paver
