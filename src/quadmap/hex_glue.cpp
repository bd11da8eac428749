#include "src/quadmap/hex_glue.hpp"

#include <algorithm>

namespace loom::quadmap {

bool plan_gluing(const QuadMap& m, const std::vector<Dart>& twin, const std::vector<int>& degree, Gluing g,
                 GluedHex& out) {
  const Quad& b = m.quads[g.bottom];
  std::array<Vertex, 4> t{no_vertex, no_vertex, no_vertex, no_vertex};
  out.k = 1;
  out.covered[0] = g.bottom;
  auto set_top = [&t](int i, Vertex v) {
    if (t[i] != no_vertex && t[i] != v) return false;
    t[i] = v;
    return true;
  };
  for (int i = 0; i < 4; ++i) {
    if (!(g.sides >> i & 1)) continue;
    const Dart back = twin[4 * g.bottom + static_cast<Dart>(i)];  // b_{i+1} -> b_i in the side quad
    const std::uint32_t side = back / 4;
    for (int c = 0; c < out.k; ++c)
      if (out.covered[c] == side) return false;
    const Quad& s = m.quads[side];
    const unsigned j = back % 4;
    if (!set_top(i, s[(j + 2) % 4]) || !set_top((i + 1) % 4, s[(j + 3) % 4])) return false;
    out.covered[out.k++] = side;
  }
  Vertex fresh = m.vertex_bound;
  for (Vertex& v : t)
    if (v == no_vertex) v = fresh++;
  out.hex = {b[0], b[3], b[2], b[1], t[0], t[3], t[2], t[1]};
  for (int i = 0; i < 8; ++i)
    for (int j = i + 1; j < 8; ++j)
      if (out.hex[i] == out.hex[j]) return false;

  // A hex vertex on p covered quads goes from degree d to d + 3 - 2p.
  for (Vertex v : out.hex) {
    if (v >= m.vertex_bound) continue;
    int p = 0;
    for (int c = 0; c < out.k; ++c)
      for (Vertex w : m.quads[out.covered[c]]) p += w == v;
    const int after = degree[v] + 3 - 2 * p;
    if (after != 0 && after < 3) return false;
  }

  out.vertex_bound = fresh;
  std::size_t n = 0;
  out.added[n++] = {t[0], t[1], t[2], t[3]};
  for (int i = 0; i < 4; ++i)
    if (!(g.sides >> i & 1)) out.added[n++] = {b[i], b[(i + 1) % 4], t[(i + 1) % 4], t[i]};
  return true;
}

QuadMap after_gluing(const QuadMap& m, const GluedHex& planned) {
  QuadMap after;
  after.vertex_bound = planned.vertex_bound;
  after.quads.reserve(m.size() + 6 - 2 * static_cast<std::size_t>(planned.k));
  const auto* covered_end = planned.covered.begin() + planned.k;
  for (std::uint32_t q = 0; q < m.size(); ++q)
    if (std::find(planned.covered.begin(), covered_end, q) == covered_end) after.quads.push_back(m.quads[q]);
  for (int a = 0; a < 6 - planned.k; ++a) after.quads.push_back(planned.added[static_cast<std::size_t>(a)]);
  return after;
}

std::vector<Dart> twins_after_gluing(const QuadMap& m, const std::vector<Dart>& twin, const GluedHex& planned) {
  const auto* covered_end = planned.covered.begin() + planned.k;
  constexpr std::uint32_t gone = 0xffffffffu;
  std::vector<std::uint32_t> renumbered(m.size(), gone);
  std::uint32_t kept = 0;
  for (std::uint32_t q = 0; q < m.size(); ++q)
    if (std::find(planned.covered.begin(), covered_end, q) == covered_end) renumbered[q] = kept++;
  const auto added = static_cast<std::uint32_t>(6 - planned.k);
  std::vector<Dart> out(4 * static_cast<std::size_t>(kept + added), no_dart);
  // Darts whose twin was covered or is added: all on the hex's edges, a few dozen at most.
  std::vector<std::pair<Dart, std::array<Vertex, 2>>> open;
  for (std::uint32_t q = 0; q < m.size(); ++q) {
    if (renumbered[q] == gone) continue;
    for (Dart i = 0; i < 4; ++i) {
      const Dart t = twin[4 * q + i], d = 4 * renumbered[q] + i;
      if (t != no_dart && renumbered[t / 4] != gone)
        out[d] = 4 * renumbered[t / 4] + t % 4;
      else
        open.push_back({d, {m.tail(4 * q + i), m.head(4 * q + i)}});
    }
  }
  for (std::uint32_t a = 0; a < added; ++a) {
    const Quad& quad = planned.added[a];
    for (Dart i = 0; i < 4; ++i) open.push_back({4 * (kept + a) + i, {quad[i], quad[(i + 1) % 4]}});
  }
  for (const auto& [d, edge] : open)
    for (const auto& [e, back] : open)
      if (back[0] == edge[1] && back[1] == edge[0]) {
        out[d] = e;
        break;
      }
  return out;
}

std::vector<int> degrees_after_gluing(const QuadMap& m, const std::vector<int>& degree, const GluedHex& planned) {
  std::vector<int> out = degree;
  out.resize(std::max<std::size_t>(planned.vertex_bound, m.vertex_bound), 0);
  for (int c = 0; c < planned.k; ++c)
    for (Vertex v : m.quads[planned.covered[static_cast<std::size_t>(c)]]) --out[v];
  for (int a = 0; a < 6 - planned.k; ++a)
    for (Vertex v : planned.added[static_cast<std::size_t>(a)]) ++out[v];
  return out;
}

bool glue_hex(const QuadMap& m, const std::vector<Dart>& twin, const std::vector<int>& degree, Gluing g,
              GluedHex& out) {
  if (!plan_gluing(m, twin, degree, g, out)) return false;
  out.after = after_gluing(m, out);
  return true;
}

bool fill_cube(const QuadMap& m, const std::vector<Dart>& twin, Hex& out) {
  if (m.size() != 6) return false;
  const Quad& b = m.quads[0];
  std::array<Vertex, 4> t{};
  for (int i = 0; i < 4; ++i) {
    const Dart back = twin[static_cast<Dart>(i)];
    if (back == no_dart) return false;
    const Quad& s = m.quads[back / 4];
    t[i] = s[(back % 4 + 2) % 4];
  }
  out = {b[0], b[3], b[2], b[1], t[0], t[3], t[2], t[1]};
  // The map is the cube exactly when the hex's outward faces are its quads.
  auto faces = outward_faces(out);
  for (const Quad& f : faces) {
    bool found = false;
    for (const Quad& q : m.quads)
      for (int r = 0; r < 4 && !found; ++r)
        found = q[r] == f[0] && q[(r + 1) % 4] == f[1] && q[(r + 2) % 4] == f[2] && q[(r + 3) % 4] == f[3];
    if (!found) return false;
  }
  return true;
}

std::array<Quad, 6> outward_faces(const Hex& h) {
  return {Quad{h[0], h[3], h[2], h[1]}, Quad{h[4], h[5], h[6], h[7]}, Quad{h[0], h[1], h[5], h[4]},
          Quad{h[1], h[2], h[6], h[5]}, Quad{h[2], h[3], h[7], h[6]}, Quad{h[3], h[0], h[4], h[7]}};
}

}  // namespace loom::quadmap
