#pragma once
// How the mesh readers and checks word a refusal: "<file>: <place>: <what is wrong; the fix>".
// Shared so that every format names places the same way (line N, byte offset N, vertex N).
#include "core/input_error.h"
#include "core/printable.h"
#include <glm/vec3.hpp>

#include <cstdint>
#include <sstream>
#include <string>
#include <string_view>

namespace paver::mesh_detail {

[[noreturn]] inline void fail(const std::string& source, const std::string& what) {
  throw InputError(source + ": " + what);
}

inline std::string count_of(long long n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

inline std::string at_line(long long line) { return "line " + std::to_string(line) + ": "; }

inline std::string at_byte(std::uint64_t offset) { return "byte offset " + std::to_string(offset) + ": "; }

// 'text', cut to `max` characters: a token from the file, shown as found.
// A piece of a file in a message, quoted and made printable (core/printable.h).
inline std::string quoted(std::string_view text, size_t max = 40) {
  std::string out = "'";  // appended piece by piece: chained operator+ trips GCC 12's -Wrestrict
  out += printable(text.substr(0, max), true);
  out += '\'';
  return out;
}

inline std::string format_point(const glm::dvec3& p) {
  std::ostringstream out;
  out << '(' << p.x << ", " << p.y << ", " << p.z << ')';
  return out.str();
}

}  // namespace paver::mesh_detail
