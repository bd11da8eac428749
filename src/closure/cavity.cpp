#include "src/closure/cavity.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "src/closure/hex_meeting.hpp"
#include "src/util/bits.hpp"

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

std::pair<std::uint32_t, std::uint32_t> unordered(std::uint32_t a, std::uint32_t b) { return {std::min(a, b), std::max(a, b)}; }

/// Whether quads `q` and `p` (distinct) are compatible in a proper map.
bool compatible(const Quad& q, const Quad& p) {
  // Every conflict needs two shared corners; most neighbours share one.
  int shared = 0;
  for (std::uint32_t a : q)
    for (std::uint32_t b : p) shared += a == b;
  if (shared < 2) return true;
  const std::pair<std::uint32_t, std::uint32_t> dq[2] = {unordered(q[0], q[2]), unordered(q[1], q[3])};
  const std::pair<std::uint32_t, std::uint32_t> dp[2] = {unordered(p[0], p[2]), unordered(p[1], p[3])};
  for (int i = 0; i < 4; ++i) {
    const std::uint32_t a = q[i], b = q[(i + 1) % 4];
    for (int j = 0; j < 4; ++j) {
      if (a == p[j] && b == p[(j + 1) % 4]) return false;  // a directed edge run twice: a repeated edge
      if (unordered(p[j], p[(j + 1) % 4]) == dq[0] || unordered(p[j], p[(j + 1) % 4]) == dq[1]) return false;
    }
    const auto e = unordered(a, b);
    if (e == dp[0] || e == dp[1]) return false;
  }
  return dq[0] != dp[0] && dq[0] != dp[1] && dq[1] != dp[0] && dq[1] != dp[1];
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
      std::uint8_t in_quad = 0, in_hex = 0;
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 8; ++j)
          if (quad[static_cast<std::size_t>(i)] == hex[static_cast<std::size_t>(j)]) {
            in_quad |= static_cast<std::uint8_t>(1u << i);
            in_hex |= static_cast<std::uint8_t>(1u << j);
          }
      const int n = bits_set(in_quad);
      const bool quad_edge = in_quad == 0b0011 || in_quad == 0b0110 || in_quad == 0b1100 || in_quad == 0b1001;
      if (n >= 3 || (n == 2 && !(quad_edge && is_hex_edge(in_hex)))) ok = false;
    });
  return ok;
}

}  // namespace loom::closure
