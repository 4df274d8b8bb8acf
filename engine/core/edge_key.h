#pragma once
// One 64-bit key for the undirected edge between two vertex indices: the same whichever way round.
#include <algorithm>
#include <cstdint>

namespace paver {

inline std::uint64_t edge_key(int a, int b) {
  return (std::uint64_t(std::uint32_t(std::min(a, b))) << 32) | std::uint32_t(std::max(a, b));
}

}  // namespace paver
