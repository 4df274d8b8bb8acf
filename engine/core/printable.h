#pragma once
// Text from a file or a command line made safe to show on a terminal: control bytes (NUL,
// escape sequences, ...) and DEL are written as \xNN, so a message is never cut at a NUL nor drives
// the terminal. With `ascii_only`, bytes from 0x80 on too (file contents that may be binary);
// without, UTF-8 names such as "bagué.obj" are kept.
#include <cstddef>
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

// The longest message line the programs print: a value quoted from a file or a flag is cut to fit.
inline constexpr std::size_t kMaxMessageBytes = 2000;

// `text` made printable and, when longer than `max` bytes, cut in its middle ("/home/.../out"), so
// that a 5,000-character path or a 60 MB value makes a line a terminal can show.
inline std::string printable_cut(std::string_view text, std::size_t max = 160) {
  std::string shown = printable(text);
  if (shown.size() <= max) return shown;
  const std::size_t keep = max / 2;
  return shown.substr(0, keep) + "[... " + std::to_string(shown.size() - 2 * keep) + " bytes ...]" +
         shown.substr(shown.size() - keep);
}

}  // namespace paver
