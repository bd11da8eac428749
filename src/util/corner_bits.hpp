#pragma once
// Which corners of one cell are corners of another, as bits, comparing four
// corners at once (GCC and Clang vector extensions: SSE2 on the baseline
// x86-64 the project builds for, plain code elsewhere). The closure search
// asks this for every quad round every gluing it tries, millions of times a
// second; corner by corner it was a quarter of the search.
#include <array>
#include <cstdint>
#include <cstring>

namespace loom {

namespace corner_bits_detail {

using Lanes = std::uint32_t __attribute__((vector_size(16)));

inline Lanes lanes(const std::uint32_t* four) {
  Lanes l;
  std::memcpy(&l, four, sizeof l);
  return l;
}

/// Lanes of `x` equal to any of the n values at `of`: all ones, else zero.
template <std::size_t N>
inline Lanes among(Lanes x, const std::array<std::uint32_t, N>& of) {
  Lanes hit = x == of[0];
  for (std::size_t i = 1; i < N; ++i) hit |= x == of[i];
  return hit;
}

/// Bit i set when lane i is all ones.
inline std::uint8_t mask(Lanes hit) {
  const Lanes bit = hit & Lanes{1, 2, 4, 8};
  return static_cast<std::uint8_t>(bit[0] | bit[1] | bit[2] | bit[3]);
}

}  // namespace corner_bits_detail

/// Bit i (of the first M, M = 4 or 8) set when corner i of `a` is a corner of `b`.
template <std::size_t M, std::size_t N>
inline std::uint8_t corners_among(const std::array<std::uint32_t, M>& a, const std::array<std::uint32_t, N>& b) {
  static_assert(M == 4 || M == 8, "cells of 4 or 8 corners");
  using namespace corner_bits_detail;
  std::uint8_t bits = mask(among(lanes(a.data()), b));
  if constexpr (M == 8) bits |= static_cast<std::uint8_t>(mask(among(lanes(a.data() + 4), b)) << 4);
  return bits;
}

}  // namespace loom
