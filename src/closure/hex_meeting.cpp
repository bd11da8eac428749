#include "src/closure/hex_meeting.hpp"

#include <algorithm>

#include "src/util/bits.hpp"
#include "src/util/corner_bits.hpp"

namespace loom::closure {

namespace {

constexpr std::array<std::uint8_t, 12> kEdges = {
    0b00000011, 0b00000110, 0b00001100, 0b00001001,   // 01 12 23 30
    0b00110000, 0b01100000, 0b11000000, 0b10010000,   // 45 56 67 74
    0b00010001, 0b00100010, 0b01000100, 0b10001000};  // 04 15 26 37
constexpr std::array<std::uint8_t, 6> kFaces = {0b00001111, 0b11110000, 0b00110011,
                                                0b01100110, 0b11001100, 0b10011001};

}  // namespace

std::uint8_t shared_corners(const Hex& a, const Hex& b) { return corners_among(a, b); }

bool is_hex_edge(std::uint8_t corners) { return std::find(kEdges.begin(), kEdges.end(), corners) != kEdges.end(); }
bool is_hex_face(std::uint8_t corners) { return std::find(kFaces.begin(), kFaces.end(), corners) != kFaces.end(); }

bool meets_as_glued(const Hex& glued, const Hex& other, const std::vector<const Quad*>& onto) {
  const std::uint8_t in_glued = shared_corners(glued, other);
  const int n = bits_set(in_glued);
  if (n <= 1) return true;
  if (n != 2 && n != 4) return false;
  const std::uint8_t in_other = shared_corners(other, glued);
  if (n == 2 ? !(is_hex_edge(in_glued) && is_hex_edge(in_other)) : !(is_hex_face(in_glued) && is_hex_face(in_other)))
    return false;
  // The shared corners must all be corners of one quad it is glued onto.
  for (const Quad* q : onto) {
    bool all = true;
    for (int i = 0; i < 8 && all; ++i)
      if (in_glued >> i & 1) all = std::find(q->begin(), q->end(), glued[static_cast<std::size_t>(i)]) != q->end();
    if (all) return true;
  }
  return false;
}

}  // namespace loom::closure
