#include "src/closure/irregularity.hpp"

#include <algorithm>
#include <utility>

#include "src/check/edge_valence.hpp"
#include "src/check/hex_topology.hpp"

namespace loom::closure {

namespace {

bool quad_has_side(const Quad& q, std::uint32_t u, std::uint32_t v) {
  for (std::size_t i = 0; i < 4; ++i) {
    const std::uint32_t a = q[i], b = q[(i + 1) % 4];
    if ((a == u && b == v) || (a == v && b == u)) return true;
  }
  return false;
}

template <class F>
void for_each_hex_edge(const Hex& hex, F&& f) {
  for (const auto& e : kHexEdgeCorners) f(hex[static_cast<std::size_t>(e[0])], hex[static_cast<std::size_t>(e[1])]);
}

}  // namespace

bool hex_has_edge(const Hex& hex, std::uint32_t u, std::uint32_t v) {
  bool found = false;
  for_each_hex_edge(hex, [&](std::uint32_t a, std::uint32_t b) { found = found || (a == u && b == v) || (a == v && b == u); });
  return found;
}

int gluing_irregularity(const quadmap::GluedHex& glued, const quadmap::QuadMap& front,
                        const std::vector<std::int32_t>& owner, const QuadsAtVertex& at,
                        const std::vector<std::uint32_t>& covered, const HexesRound& round) {
  int change = 0;
  for_each_hex_edge(glued.hex, [&](std::uint32_t u, std::uint32_t v) {
    if (u >= front.vertex_bound || v >= front.vertex_bound) return;  // a new edge: one hex, on the front
    bool surface = false, on_front = false;
    at.each(u, [&](std::uint32_t q) {
      if (!quad_has_side(front.quads[q], u, v)) return;
      surface = surface || owner[q] < 0;
      on_front = on_front || std::find(covered.begin(), covered.end(), q) == covered.end();
    });
    if (surface) return;
    for (int a = 0; a < 6 - glued.k; ++a)
      on_front = on_front || quad_has_side(glued.added[static_cast<std::size_t>(a)], u, v);
    const int before = round(u, v);
    change += edge_irregularity(before + 1, !on_front) - edge_irregularity(before, false);
  });
  return change;
}

int closing_irregularity(const std::vector<Hex>& hexes, const quadmap::QuadMap& front,
                         const std::vector<std::int32_t>& owner, const HexesRound& round) {
  const QuadsAtVertex at(front);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  for (const Hex& h : hexes)
    for_each_hex_edge(h, [&](std::uint32_t u, std::uint32_t v) { edges.emplace_back(std::min(u, v), std::max(u, v)); });
  std::sort(edges.begin(), edges.end());
  int change = 0;
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    const auto [u, v] = edges[i];
    const int added = static_cast<int>(j - i);
    i = j;
    int before = 0;
    if (v < front.vertex_bound) {  // both ends were there already
      bool surface = false;
      at.each(u, [&](std::uint32_t q) { surface = surface || (owner[q] < 0 && quad_has_side(front.quads[q], u, v)); });
      if (surface) continue;
      before = round(u, v);
    }
    change += edge_irregularity(before + added, true) - edge_irregularity(before, false);
  }
  return change;
}

}  // namespace loom::closure
