#include "src/quadmap/quad_map.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>

#include <fmt/format.h>

#include "src/util/by_corner.hpp"

namespace loom::quadmap {

namespace {

std::uint64_t key(Vertex from, Vertex to) { return std::uint64_t(from) << 32 | to; }

/// Number of darts leaving `v` reached by turning round it from `start`; the
/// whole ring when the quads round v form one cycle.
std::size_t ring_length(const QuadMap& m, const std::vector<Dart>& twin, Dart start) {
  std::size_t n = 0;
  Dart d = start;
  do {
    ++n;
    d = twin[prev_in_quad(d)];
  } while (d != start && d != no_dart && n <= 4 * m.size());
  return n;
}

/// twins() for maps whose vertex ids are sparse: darts sorted by (tail, head).
std::vector<Dart> twins_by_sorting(const QuadMap& m, Dart* duplicate) {
  std::vector<std::pair<std::uint64_t, Dart>> darts;
  darts.reserve(4 * m.size());
  for (Dart d = 0; d < 4 * m.size(); ++d) darts.emplace_back(key(m.tail(d), m.head(d)), d);
  std::sort(darts.begin(), darts.end());
  std::vector<Dart> twin(darts.size(), no_dart);
  for (std::size_t i = 0; i + 1 < darts.size(); ++i)
    if (darts[i].first == darts[i + 1].first && (i == 0 || darts[i - 1].first != darts[i].first) && duplicate)
      *duplicate = darts[i].second;
  for (const auto& [k, d] : darts) {
    const std::uint64_t back = key(static_cast<Vertex>(k & 0xffffffffu), static_cast<Vertex>(k >> 32));
    auto it = std::lower_bound(darts.begin(), darts.end(), std::make_pair(back, Dart{0}));
    if (it != darts.end() && it->first == back) twin[d] = it->second;
  }
  return twin;
}

}  // namespace

std::vector<Dart> twins(const QuadMap& m, Dart* duplicate) {
  const auto darts = static_cast<Dart>(4 * m.size());
  std::uint64_t top = 0;
  for (const Quad& q : m.quads)
    for (Vertex v : q) top = std::max<std::uint64_t>(top, std::uint64_t{v} + 1);
  if (top > 2 * std::uint64_t{darts} + 64) return twins_by_sorting(m, duplicate);
  // A dart's twin is among the few darts leaving its head (ascending there).
  const ByCorner<Dart> leaving(
      darts, [&m](std::size_t d) { return std::array<Vertex, 1>{m.tail(static_cast<Dart>(d))}; },
      [](std::size_t d) { return static_cast<Dart>(d); });
  std::vector<Dart> twin(darts, no_dart);
  std::uint64_t repeated = 0;  // the greatest (tail, head) run twice, plus one
  for (Dart d = 0; d < darts; ++d) {
    const Vertex t = m.tail(d), h = m.head(d);
    leaving.each(h, [&](Dart e) {
      if (twin[d] == no_dart && m.head(e) == t) twin[d] = e;
    });
    if (!duplicate) continue;
    leaving.each(t, [&](Dart e) {
      if (e != d && m.head(e) == h && key(t, h) + 1 > repeated) {
        repeated = key(t, h) + 1;
        *duplicate = std::min(d, e);
      }
    });
  }
  return twin;
}

std::vector<int> degrees(const QuadMap& m) {
  std::vector<int> deg(m.vertex_bound, 0);
  for (const Quad& q : m.quads)
    for (Vertex v : q) ++deg[v];
  return deg;
}

std::string why_not_simple(const QuadMap& m) {
  for (std::size_t q = 0; q < m.size(); ++q) {
    const Quad& c = m.quads[q];
    for (int i = 0; i < 4; ++i) {
      if (c[i] >= m.vertex_bound) return fmt::format("quad {} has vertex {} out of range", q, c[i]);
      for (int j = i + 1; j < 4; ++j)
        if (c[i] == c[j]) return fmt::format("quad {} repeats vertex {}", q, c[i]);
    }
  }
  Dart duplicate = no_dart;
  const auto twin = twins(m, &duplicate);
  if (duplicate != no_dart)
    return fmt::format("edge {}-{} is run the same way by two quads", m.tail(duplicate), m.head(duplicate));
  for (Dart d = 0; d < twin.size(); ++d)
    if (twin[d] == no_dart) return fmt::format("edge {}-{} of quad {} is open", m.tail(d), m.head(d), d / 4);
  const auto deg = degrees(m);
  std::vector<bool> ring_seen(m.vertex_bound, false);
  for (Dart d = 0; d < twin.size(); ++d) {
    const Vertex v = m.tail(d);
    if (ring_seen[v]) continue;
    ring_seen[v] = true;
    if (ring_length(m, twin, d) != static_cast<std::size_t>(deg[v]))
      return fmt::format("the quads at vertex {} do not form one cycle", v);
  }
  for (Vertex v = 0; v < m.vertex_bound; ++v) {
    if (deg[v] > 0 && deg[v] < 3) return fmt::format("vertex {} is on {} quads, fewer than 3", v, deg[v]);
  }
  // Each undirected edge is run once each way, so a repeated edge shows as
  // two darts with one (tail, head) pair, which twins() reported above.
  return {};
}

std::string why_not_proper(const QuadMap& m) {
  if (auto why = why_not_simple(m); !why.empty()) return why;
  std::vector<std::uint64_t> edges, diagonals;
  for (std::size_t q = 0; q < m.size(); ++q) {
    const Quad& c = m.quads[q];
    for (int i = 0; i < 4; ++i) edges.push_back(key(std::min(c[i], c[(i + 1) % 4]), std::max(c[i], c[(i + 1) % 4])));
    diagonals.push_back(key(std::min(c[0], c[2]), std::max(c[0], c[2])));
    diagonals.push_back(key(std::min(c[1], c[3]), std::max(c[1], c[3])));
  }
  std::sort(edges.begin(), edges.end());
  std::sort(diagonals.begin(), diagonals.end());
  for (std::size_t i = 0; i + 1 < diagonals.size(); ++i)
    if (diagonals[i] == diagonals[i + 1])
      return fmt::format("two quads have opposite corners {} and {}", diagonals[i] >> 32, diagonals[i] & 0xffffffffu);
  for (std::uint64_t d : diagonals)
    if (std::binary_search(edges.begin(), edges.end(), d))
      return fmt::format("an edge joins {} and {}, opposite corners of a quad", d >> 32, d & 0xffffffffu);
  return {};
}

bool is_three_connected(const QuadMap& m) {
  const std::uint32_t n = m.vertex_bound;
  std::vector<std::vector<Vertex>> adj(n);
  for (const Quad& q : m.quads)
    for (int i = 0; i < 4; ++i) adj[q[i]].push_back(q[(i + 1) % 4]);
  std::vector<Vertex> used;
  for (Vertex v = 0; v < n; ++v)
    if (!adj[v].empty()) used.push_back(v);
  if (used.size() < 4) return false;
  std::vector<std::uint8_t> seen(n);
  std::vector<Vertex> stack;
  for (std::size_t i = 0; i < used.size(); ++i)
    for (std::size_t j = i + 1; j < used.size(); ++j) {
      std::fill(seen.begin(), seen.end(), 0);
      seen[used[i]] = seen[used[j]] = 1;
      const Vertex start = used[i == 0 ? (j == 1 ? 2 : 1) : 0];
      seen[start] = 1;
      stack.assign(1, start);
      std::size_t reached = 1;
      while (!stack.empty()) {
        const Vertex v = stack.back();
        stack.pop_back();
        for (Vertex w : adj[v])
          if (!seen[w]) {
            seen[w] = 1;
            ++reached;
            stack.push_back(w);
          }
      }
      if (reached != used.size() - 2) return false;
    }
  return true;
}

QuadMap mirrored(const QuadMap& m) {
  QuadMap r = m;
  for (Quad& q : r.quads) std::swap(q[1], q[3]);
  return r;
}

std::vector<Dart> mirrored_twins(const std::vector<Dart>& twin) {
  auto flip = [](Dart d) { return (d & ~3u) | (3u - (d & 3u)); };
  std::vector<Dart> out(twin.size(), no_dart);
  for (Dart d = 0; d < twin.size(); ++d)
    if (const Dart t = twin[flip(d)]; t != no_dart) out[d] = flip(t);
  return out;
}

QuadMap pseudo_double_wheel(int quads) {
  if (quads < 6 || quads % 2 != 0) throw std::logic_error("pseudo_double_wheel: needs an even count >= 6");
  const auto cycle = static_cast<Vertex>(quads);
  const Vertex top = cycle, bottom = cycle + 1;
  QuadMap m;
  m.vertex_bound = cycle + 2;
  auto c = [cycle](Vertex i) { return i % cycle; };
  for (Vertex i = 0; i < cycle; i += 2) {
    m.quads.push_back({top, c(i), c(i + 1), c(i + 2)});
    m.quads.push_back({bottom, c(i + 3), c(i + 2), c(i + 1)});
  }
  return m;
}

QuadMap from_surface(const QuadSurface& s) {
  QuadMap m;
  m.quads = s.quads;
  m.vertex_bound = static_cast<std::uint32_t>(s.points.size());
  for (const Quad& q : s.quads)
    for (Vertex v : q) m.vertex_bound = std::max(m.vertex_bound, v + 1);
  return m;
}

}  // namespace loom::quadmap
