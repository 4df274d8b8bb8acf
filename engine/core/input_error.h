#pragma once
// A problem with something the user gave us (a file, a flag, a design). The CLI prints what()
// and exits with code 2; the editor shows it. Messages name the file, the place and the fix.
#include <stdexcept>
#include <string>

namespace paver {

class InputError : public std::runtime_error {
public:
  // A NUL from a file or a flag is written \x00: what() is read up to the first NUL, which cut
  // the message short there.
  explicit InputError(const std::string& message) : std::runtime_error(without_nul(message)) {}

private:
  static std::string without_nul(const std::string& message) {
    if (message.find('\0') == std::string::npos) return message;
    std::string out;
    for (const char c : message) out += c == '\0' ? std::string("\\x00") : std::string(1, c);
    return out;
  }
};

// An InputError about one of the design's keys found past the file's own validation (its unit cell,
// its elements' overlaps, its edits, its placement), which does not know the file: the pipeline
// names the file in front of it.
class DesignError : public InputError {
public:
  using InputError::InputError;
};

}  // namespace paver
