#pragma once
// Random draws that are the same on every standard library: the standard
// distributions (uniform_int_distribution, ...) are implementation-defined, so
// generators seeded for reproducible output draw through these instead. Only
// the raw 64-bit output of std::mt19937_64, which the standard fixes, is used.
#include <cstdint>
#include <random>

namespace loom::gen {

/// A uniform integer in [0, n), n > 0: raw draws beyond the largest multiple of
/// n are rejected, so there is no modulo bias.
inline std::uint64_t uniform_index(std::mt19937_64& rng, std::uint64_t n) {
  const std::uint64_t limit = UINT64_MAX - UINT64_MAX % n;
  std::uint64_t x = rng();
  while (x >= limit) x = rng();
  return x % n;
}

/// A uniform double in [-1, 1), from the top 53 bits of one draw.
inline double uniform_signed_unit(std::mt19937_64& rng) { return double(rng() >> 11) * 0x1.0p-52 - 1.0; }

}  // namespace loom::gen
