#include "src/closure/cavity.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "src/closure/hex_meeting.hpp"
#include "src/util/bits.hpp"
#include "src/util/corner_bits.hpp"

namespace loom::closure {

using quadmap::QuadMap;

Cavity surface_cavity(const QuadMap& surface) {
  return {surface, std::vector<std::int32_t>(surface.size(), -1), {}};
}

std::string why_not_closable(const Cavity& c) {
  if (c.owner.size() != c.front.size()) return "the front and its owners differ in size";
  if (auto why = quadmap::why_not_proper(c.front); !why.empty()) return "the front is not proper: " + why;
  for (std::size_t q = 0; q < c.front.size(); ++q) {
    const std::int32_t h = c.owner[q];
    if (h < 0) continue;
    if (static_cast<std::size_t>(h) >= c.hexes.size()) return fmt::format("front quad {} has no such owner {}", q, h);
    const Hex& hex = c.hexes[static_cast<std::size_t>(h)];
    for (std::uint32_t v : c.front.quads[q])
      if (std::find(hex.begin(), hex.end(), v) == hex.end())
        return fmt::format("front quad {} is not a face of its owner, hex {}", q, h);
  }
  return {};
}

HexesAtVertex::HexesAtVertex(const std::vector<Hex>& hexes) {
  for (std::size_t h = 0; h < hexes.size(); ++h) add(hexes[h], static_cast<std::int32_t>(h));
}

void HexesAtVertex::add(const Hex& hex, std::int32_t index) {
  for (std::uint32_t v : hex) {
    if (v >= at_.size()) at_.resize(v + 1);
    at_[v].push_back(index);
  }
}

const std::vector<std::int32_t>& HexesAtVertex::at(std::uint32_t v) const { return v < at_.size() ? at_[v] : none_; }

namespace {

/// The corner a two-corner mask of a quad starts its edge at (0b0110: the
/// edge from corner 1 to 2), or -1 when the two corners are opposite.
int edge_start(std::uint8_t corners) {
  switch (corners) {
    case 0b0011: return 0;
    case 0b0110: return 1;
    case 0b1100: return 2;
    case 0b1001: return 3;
    default: return -1;
  }
}

/// Whether quads `q` and `p` (distinct) can both be in a proper map, which
/// forbids a shared diagonal, an edge of one that is a diagonal of the other,
/// and an edge run the same way by both. So they can when they share at most
/// one corner, or two that are an edge of both, run opposite ways; any three
/// corners of q hold one of its diagonals.
bool compatible(const Quad& q, const Quad& p) {
  const std::uint8_t in_q = corners_among(q, p);
  const int shared = bits_set(in_q);
  if (shared < 2) return true;
  if (shared > 2) return false;
  const int i = edge_start(in_q), j = edge_start(corners_among(p, q));
  return i >= 0 && j >= 0 && p[static_cast<std::size_t>(j)] == q[static_cast<std::size_t>((i + 1) % 4)];
}

}  // namespace

bool glued_front_is_proper(const QuadMap& before, const QuadsAtVertex& at, const quadmap::GluedHex& glued) {
  const auto added = static_cast<std::size_t>(6 - glued.k);
  auto covered = [&glued](std::uint32_t q) {
    return std::find(glued.covered.begin(), glued.covered.begin() + glued.k, q) != glued.covered.begin() + glued.k;
  };
  for (std::size_t n = 0; n < added; ++n) {
    const Quad& q = glued.added[n];
    for (std::size_t m = 0; m < added; ++m)
      if (m != n && !compatible(q, glued.added[m])) return false;
    for (std::uint32_t v : q) {
      bool ok = true;
      at.each(v, [&](std::uint32_t old) { ok = ok && (covered(old) || compatible(q, before.quads[old])); });
      if (!ok) return false;
    }
  }
  return true;
}

bool touches_front_properly(const Hex& hex, const QuadMap& front, const QuadsAtVertex& at,
                            const std::vector<std::uint32_t>& covered) {
  bool ok = true;
  for (std::uint32_t v : hex)
    at.each(v, [&](std::uint32_t q) {
      if (!ok || std::find(covered.begin(), covered.end(), q) != covered.end()) return;
      const Quad& quad = front.quads[q];
      const std::uint8_t in_quad = corners_among(quad, hex);
      const int n = bits_set(in_quad);
      if (n < 2) return;
      if (n >= 3 || edge_start(in_quad) < 0 || !is_hex_edge(corners_among(hex, quad))) ok = false;
    });
  return ok;
}

}  // namespace loom::closure
