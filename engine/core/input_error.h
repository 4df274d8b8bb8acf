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

// An InputError about one of the design's keys found past the file's own validation (its unit cell,
// its elements' overlaps, its edits, its placement), which does not know the file: the pipeline
// names the file in front of it.
class DesignError : public InputError {
public:
  using InputError::InputError;
};

}  // namespace paver
