#pragma once
// A front's key in the closure search: the exclusive or of a hash of each of
// its quads taken as a set of corners, so that a gluing updates it in O(k)
// (out go the k quads covered, in the 6 - k added) and two gluings that leave
// the same quads give the same key.
#include <algorithm>
#include <cstdint>

#include "src/mesh/quad_surface.hpp"

namespace loom::closure {

inline std::uint64_t quad_hash(const Quad& q) {
  Quad s = q;
  std::sort(s.begin(), s.end());
  std::uint64_t h = 0x9E3779B97F4A7C15ull;
  for (std::uint32_t v : s) {
    h ^= v + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
    h *= 0xBF58476D1CE4E5B9ull;
  }
  return h ^ (h >> 31);
}

}  // namespace loom::closure
