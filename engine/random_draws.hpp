#pragma once
// Seeded draws that give the same numbers on every standard library.
//
// The standard fixes the raw output of std::mt19937_64 but not what
// std::uniform_int_distribution or std::shuffle make of it, so a seeded
// strategy would weave differently under another toolchain. These are written
// out here instead, and chosen to draw exactly what GCC 12's libstdc++ draws
// from a 64-bit generator (Debian 12's, on which the project's figures were
// measured): the figures stay, and now hold everywhere.
// tests/test_random_draws.cpp checks both.
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <random>
#include <utility>

namespace loom::engine {

/// The 128-bit product a x b as its high and low halves, from 32-bit limbs
/// (there is no standard 128-bit integer).
struct Product128 {
  std::uint64_t high, low;
};
inline Product128 multiply_wide(std::uint64_t a, std::uint64_t b) {
  const std::uint64_t a_lo = a & 0xffffffffu, a_hi = a >> 32, b_lo = b & 0xffffffffu, b_hi = b >> 32;
  const std::uint64_t lo_lo = a_lo * b_lo, hi_lo = a_hi * b_lo, lo_hi = a_lo * b_hi, hi_hi = a_hi * b_hi;
  const std::uint64_t middle = (lo_lo >> 32) + (hi_lo & 0xffffffffu) + lo_hi;
  return {hi_hi + (hi_lo >> 32) + (middle >> 32), (middle << 32) | (lo_lo & 0xffffffffu)};
}

/// A uniform integer in [0, n), n > 0, by Lemire's nearly divisionless method
/// ("Fast random integer generation in an interval", ACM TOMACS 2019): the
/// high half of draw x n, redrawn while the low half falls in the biased part.
inline std::uint64_t uniform_below(std::mt19937_64& rng, std::uint64_t n) {
  Product128 p = multiply_wide(rng(), n);
  if (p.low < n) {
    const std::uint64_t threshold = (0 - n) % n;
    while (p.low < threshold) p = multiply_wide(rng(), n);
  }
  return p.high;
}

/// A uniformly random permutation of [first, last) (Fisher-Yates). While the
/// products fit in a draw, the positions of two successive swaps come from
/// one draw in [0, b (b + 1)), which halves the draws.
template <class RandomIt>
void shuffle(RandomIt first, RandomIt last, std::mt19937_64& rng) {
  const auto n = static_cast<std::uint64_t>(std::distance(first, last));
  if (n < 2) return;
  using std::swap;
  RandomIt i = first + 1;
  if (UINT64_MAX / n >= n) {
    // An even n leaves an odd number of swaps: the first one alone.
    if (n % 2 == 0) {
      swap(*i, *(first + static_cast<std::ptrdiff_t>(uniform_below(rng, 2))));
      ++i;
    }
    while (i != last) {
      const auto b = static_cast<std::uint64_t>(i - first) + 1;
      const std::uint64_t x = uniform_below(rng, b * (b + 1));
      swap(*i, *(first + static_cast<std::ptrdiff_t>(x / (b + 1))));
      ++i;
      swap(*i, *(first + static_cast<std::ptrdiff_t>(x % (b + 1))));
      ++i;
    }
    return;
  }
  for (; i != last; ++i)
    swap(*i, *(first + static_cast<std::ptrdiff_t>(uniform_below(rng, static_cast<std::uint64_t>(i - first) + 1))));
}

}  // namespace loom::engine
