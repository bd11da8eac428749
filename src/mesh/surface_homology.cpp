#include "src/mesh/surface_homology.hpp"

#include <algorithm>
#include <tuple>

namespace loom {

SurfaceEdges number_edges(const QuadSurface& surface) {
  struct Side {
    std::uint32_t low, high, quad, corner;
  };
  std::vector<Side> sides;
  sides.reserve(4 * surface.quads.size());
  for (std::uint32_t q = 0; q < surface.quads.size(); ++q)
    for (std::uint32_t k = 0; k < 4; ++k) {
      const std::uint32_t a = surface.quads[q][k], b = surface.quads[q][(k + 1) % 4];
      sides.push_back({std::min(a, b), std::max(a, b), q, k});
    }
  std::sort(sides.begin(), sides.end(),
            [](const Side& x, const Side& y) { return std::tie(x.low, x.high) < std::tie(y.low, y.high); });
  SurfaceEdges edges;
  edges.of_quad.resize(surface.quads.size());
  for (std::size_t i = 0; i < sides.size(); ++i) {
    if (i == 0 || sides[i].low != sides[i - 1].low || sides[i].high != sides[i - 1].high)
      edges.ends.push_back({sides[i].low, sides[i].high});
    edges.of_quad[sides[i].quad][sides[i].corner] = static_cast<std::uint32_t>(edges.ends.size() - 1);
  }
  return edges;
}

std::vector<std::vector<std::uint32_t>> incident_edges(const SurfaceEdges& edges, std::size_t nodes) {
  std::vector<std::vector<std::uint32_t>> incident(nodes);
  for (std::uint32_t e = 0; e < edges.ends.size(); ++e)
    for (std::uint32_t v : edges.ends[e]) incident[v].push_back(e);
  return incident;
}

NodeTree breadth_first_tree(const SurfaceEdges& edges, const std::vector<std::vector<std::uint32_t>>& incident,
                            std::uint32_t root) {
  const std::size_t n = incident.size();
  NodeTree tree{std::vector<std::uint32_t>(n, UINT32_MAX), std::vector<std::uint32_t>(n, UINT32_MAX),
                std::vector<std::uint32_t>(n, 0), {root}};
  std::vector<bool> seen(n, false);
  seen[root] = true;
  for (std::size_t i = 0; i < tree.order.size(); ++i) {
    const std::uint32_t v = tree.order[i];
    for (std::uint32_t e : incident[v]) {
      const std::uint32_t w = edges.ends[e][0] == v ? edges.ends[e][1] : edges.ends[e][0];
      if (seen[w]) continue;
      seen[w] = true;
      tree.parent_edge[w] = e;
      tree.parent[w] = v;
      tree.depth[w] = tree.depth[v] + 1;
      tree.order.push_back(w);
    }
  }
  return tree;
}

std::vector<std::uint32_t> cycle_through(const NodeTree& tree, std::uint32_t a, std::uint32_t b) {
  std::vector<std::uint32_t> from_a{a}, from_b{b};
  while (a != b) {
    if (tree.depth[a] >= tree.depth[b]) from_a.push_back(a = tree.parent[a]);
    else from_b.push_back(b = tree.parent[b]);
  }
  from_a.pop_back();  // the meeting node is the last of from_b
  std::vector<std::uint32_t> walk(from_a.begin(), from_a.end());
  walk.insert(walk.end(), from_b.rbegin(), from_b.rend());
  return walk;
}

namespace {

constexpr std::uint32_t kNone = UINT32_MAX;

// Quads on each side of every edge (two on a closed manifold surface).
std::vector<std::array<std::uint32_t, 2>> quads_of_edges(const SurfaceEdges& edges) {
  std::vector<std::array<std::uint32_t, 2>> quads(edges.ends.size(), {kNone, kNone});
  for (std::uint32_t q = 0; q < edges.of_quad.size(); ++q)
    for (std::uint32_t e : edges.of_quad[q]) quads[e][quads[e][0] == kNone ? 0 : 1] = q;
  return quads;
}

}  // namespace

SurfaceHomology surface_homology(const QuadSurface& surface) {
  SurfaceHomology h;
  h.edges = number_edges(surface);
  const auto quads = quads_of_edges(h.edges);
  const NodeTree tree =
      breadth_first_tree(h.edges, incident_edges(h.edges, surface.points.size()), surface.quads.front()[0]);
  std::vector<bool> in_tree(h.edges.ends.size(), false);
  for (std::uint32_t e : tree.parent_edge)
    if (e != kNone) in_tree[e] = true;

  // The dual tree, in breadth-first order from quad 0, across non-tree edges.
  std::vector<std::uint32_t> order{0}, parent_edge(surface.quads.size(), kNone);
  std::vector<bool> reached(surface.quads.size(), false), in_cotree(h.edges.ends.size(), false);
  reached[0] = true;
  for (std::size_t i = 0; i < order.size(); ++i)
    for (std::uint32_t e : h.edges.of_quad[order[i]]) {
      if (in_tree[e]) continue;
      const std::uint32_t other = quads[e][0] == order[i] ? quads[e][1] : quads[e][0];
      if (other == kNone || reached[other]) continue;
      reached[other] = true;
      in_cotree[e] = true;
      parent_edge[other] = e;
      order.push_back(other);
    }

  std::vector<std::uint32_t> leftover;
  for (std::uint32_t e = 0; e < h.edges.ends.size(); ++e)
    if (!in_tree[e] && !in_cotree[e]) leftover.push_back(e);
  h.words = (leftover.size() + 63) / 64;
  h.coordinates.assign(h.edges.ends.size() * h.words, 0);
  for (std::size_t i = 0; i < leftover.size(); ++i) {
    const std::uint32_t e = leftover[i];
    h.coordinates[e * h.words + i / 64] |= std::uint64_t{1} << (i % 64);
    h.cycles.push_back(cycle_through(tree, h.edges.ends[e][0], h.edges.ends[e][1]));
  }
  // Leaves first, each quad's edge to its parent takes the sum of its other
  // three, so that every quad but the root sums to zero; the root then does too.
  for (std::size_t i = order.size(); i-- > 1;) {
    const std::uint32_t q = order[i], up = parent_edge[q];
    std::uint64_t* target = h.coordinates.data() + up * h.words;
    for (std::uint32_t e : h.edges.of_quad[q]) {
      if (e == up) continue;
      const std::uint64_t* source = h.class_of_edge(e);
      for (std::size_t w = 0; w < h.words; ++w) target[w] ^= source[w];
    }
  }
  return h;
}

}  // namespace loom
