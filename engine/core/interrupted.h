#pragma once
// Thrown when the user stopped a run (Ctrl-C, the studio's reset): not an error of the input or
// of Paver. Whatever the run would have written is not written.
#include <stdexcept>

namespace paver {

class Interrupted : public std::runtime_error {
public:
  Interrupted() : std::runtime_error("interrupted") {}
};

}  // namespace paver
