#pragma once
// Builds binary fixtures (STL, OFF, PLY) in memory: text, and integers and floats of either byte
// order, appended in sequence.
#include <bit>
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>

namespace paver::test {

class ByteWriter {
public:
  explicit ByteWriter(bool big_endian = false) : big_endian_(big_endian) {}

  ByteWriter& text(std::string_view text) {
    bytes_ += text;
    return *this;
  }

  // Any integer or floating-point type, written with its own size.
  template <class T>
  ByteWriter& put(T value) {
    static_assert(std::is_arithmetic_v<T>);
    using Bits = std::conditional_t<sizeof(T) == 1, std::uint8_t,
                 std::conditional_t<sizeof(T) == 2, std::uint16_t,
                 std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>>>;
    const Bits bits = std::bit_cast<Bits>(value);
    for (size_t i = 0; i < sizeof(T); ++i) {
      const size_t shift = 8 * (big_endian_ ? sizeof(T) - 1 - i : i);
      bytes_.push_back(static_cast<char>((std::uint64_t(bits) >> shift) & 0xff));
    }
    return *this;
  }

  const std::string& bytes() const { return bytes_; }

private:
  bool big_endian_;
  std::string bytes_;
};

}  // namespace paver::test
