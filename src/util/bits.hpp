#pragma once
// Bits set in a byte, by table: std::popcount compiles to a library call on
// the baseline x86-64 the project builds for, and the closure search asks it
// millions of times a second.
#include <array>
#include <cstdint>

namespace loom {

inline constexpr std::array<std::uint8_t, 256> kBitsSet = [] {
  std::array<std::uint8_t, 256> t{};
  for (int b = 1; b < 256; ++b) t[b] = static_cast<std::uint8_t>((b & 1) + t[b >> 1]);
  return t;
}();

inline int bits_set(std::uint8_t byte) { return kBitsSet[byte]; }

}  // namespace loom
