#pragma once
// Text from a file or a command line made safe to show on a terminal: control bytes (NUL,
// escape sequences, ...) and DEL are written as \xNN, so a message is never cut at a NUL nor drives
// the terminal. With `ascii_only`, bytes from 0x80 on too (file contents that may be binary);
// without, UTF-8 names such as "bagué.obj" are kept.
#include <string>
#include <string_view>

namespace paver {

inline std::string printable(std::string_view text, bool ascii_only = false) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte == 0x7f || (ascii_only && byte >= 0x80)) {
      out += "\\x";
      out += kHex[byte >> 4];
      out += kHex[byte & 15];
    } else {
      out += c;
    }
  }
  return out;
}

}  // namespace paver
