// The checks run in the order the header lists. Nodes and quads are named by
// their 0-based position in the input (file order); node positions are quoted
// too, so a problem can be found whatever numbering a viewer uses.
#include "src/mesh/surface_validation.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <numeric>
#include <vector>

#include "src/util/error.hpp"

namespace loom {

namespace {

class UnionFind {
 public:
  explicit UnionFind(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
  std::size_t find(std::size_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  // The smaller index stays the root, so results do not depend on merge order.
  void unite(std::size_t a, std::size_t b) {
    a = find(a), b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<std::size_t> parent_;
};

std::string at(const QuadSurface& s, std::uint32_t node) {
  const Vec3& p = s.points[node];
  return fmt::format("node {} at ({}, {}, {})", node, p[0], p[1], p[2]);
}

std::string nodes_of(const Quad& q) { return fmt::format("{} {} {} {}", q[0], q[1], q[2], q[3]); }

void check_not_empty(const QuadSurface& s, const std::string& where) {
  if (s.quads.empty()) fail_input(where, "the surface has no quads", "give a closed quad surface mesh");
}

void check_finite(const QuadSurface& s, const std::string& where) {
  for (std::size_t i = 0; i < s.points.size(); ++i)
    for (double x : s.points[i])
      if (!std::isfinite(x))
        fail_input(where, fmt::format("node {} has a{} coordinate", i, std::isnan(x) ? " NaN" : "n infinite"),
                   "every coordinate must be a finite number; fix or remove that node");
}

void check_quads_well_formed(const QuadSurface& s, const std::string& where, const char* stage) {
  for (std::size_t q = 0; q < s.quads.size(); ++q) {
    const Quad& quad = s.quads[q];
    for (std::uint32_t n : quad)
      if (n >= s.points.size())
        fail_input(where, fmt::format("quad {} refers to node {}, but there are only {} nodes", q, n, s.points.size()),
                   "fix the quad's node indices");
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
        if (quad[a] == quad[b])
          fail_input(
              where,
              fmt::format("{}degenerate quad {} (nodes {}) uses node {} twice", stage, q, nodes_of(quad), quad[a]),
              "a quad needs four distinct nodes; remove the quad or fix its nodes");
  }
  std::vector<std::pair<Quad, std::size_t>> sorted;
  sorted.reserve(s.quads.size());
  for (std::size_t q = 0; q < s.quads.size(); ++q) {
    Quad key = s.quads[q];
    std::sort(key.begin(), key.end());
    sorted.emplace_back(key, q);
  }
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 1; i < sorted.size(); ++i)
    if (sorted[i].first == sorted[i - 1].first)
      fail_input(where,
                 fmt::format("{}duplicated quads {} and {} use the same nodes ({})", stage, sorted[i - 1].second,
                             sorted[i].second, nodes_of(s.quads[sorted[i].second])),
                 "remove one of them");
}

std::vector<std::uint32_t> used_nodes(const QuadSurface& s) {
  std::vector<bool> used(s.points.size(), false);
  for (const Quad& q : s.quads)
    for (std::uint32_t n : q) used[n] = true;
  std::vector<std::uint32_t> nodes;
  for (std::uint32_t i = 0; i < used.size(); ++i)
    if (used[i]) nodes.push_back(i);
  return nodes;
}

double bounding_box_diagonal(const QuadSurface& s, const std::vector<std::uint32_t>& nodes) {
  Vec3 low = s.points[nodes.front()], high = low;
  for (std::uint32_t n : nodes)
    for (int k = 0; k < 3; ++k) low[k] = std::min(low[k], s.points[n][k]), high[k] = std::max(high[k], s.points[n][k]);
  return norm(high - low);
}

// Rejects used nodes at identical positions or, when welding, merges those
// closer than the tolerance (each into the lowest-numbered node of its cluster).
// Returns how many nodes were merged away.
std::size_t handle_coincident_nodes(QuadSurface& s, const std::string& where, const SurfaceCheckOptions& options) {
  std::vector<std::uint32_t> nodes = used_nodes(s);
  const double tolerance = options.weld ? options.weld_tolerance * bounding_box_diagonal(s, nodes) : 0.0;
  std::sort(nodes.begin(), nodes.end(),
            [&](std::uint32_t a, std::uint32_t b) { return std::tie(s.points[a], a) < std::tie(s.points[b], b); });
  UnionFind clusters(s.points.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    for (std::size_t j = i + 1; j < nodes.size(); ++j) {
      const Vec3 &p = s.points[nodes[i]], &q = s.points[nodes[j]];
      if (q[0] - p[0] > tolerance) break;  // sorted by x first: no later node is close
      if (norm(q - p) > tolerance) continue;
      if (!options.weld)
        fail_input(where,
                   fmt::format("coincident nodes {} and {} are both at ({}, {}, {})", std::min(nodes[i], nodes[j]),
                               std::max(nodes[i], nodes[j]), p[0], p[1], p[2]),
                   "merge them into one node, or weld them (--weld)");
      clusters.unite(nodes[i], nodes[j]);
    }
  }
  std::size_t merged = 0;
  for (std::uint32_t n : nodes) merged += clusters.find(n) != n;
  if (merged > 0)
    for (Quad& q : s.quads)
      for (std::uint32_t& n : q) n = static_cast<std::uint32_t>(clusters.find(n));
  return merged;
}

struct HalfEdge {
  std::uint32_t low, high;  // the undirected edge
  std::uint32_t quad;
  bool forward;  // traversed low -> high by the quad
  auto key() const { return std::tie(low, high, quad); }
};

// Half-edges sorted so that the uses of each undirected edge are adjacent.
std::vector<HalfEdge> half_edges(const QuadSurface& s) {
  std::vector<HalfEdge> halves;
  halves.reserve(4 * s.quads.size());
  for (std::uint32_t q = 0; q < s.quads.size(); ++q)
    for (int k = 0; k < 4; ++k) {
      std::uint32_t a = s.quads[q][k], b = s.quads[q][(k + 1) % 4];
      halves.push_back({std::min(a, b), std::max(a, b), q, a < b});
    }
  std::sort(halves.begin(), halves.end(), [](const HalfEdge& x, const HalfEdge& y) { return x.key() < y.key(); });
  return halves;
}

// Calls visit(first, count) for each run of half-edges on one undirected edge.
template <class Visit>
void for_each_edge(const std::vector<HalfEdge>& halves, Visit visit) {
  for (std::size_t i = 0; i < halves.size();) {
    std::size_t j = i + 1;
    while (j < halves.size() && halves[j].low == halves[i].low && halves[j].high == halves[i].high) ++j;
    visit(i, j - i);
    i = j;
  }
}

std::string edge_name(const QuadSurface& s, const HalfEdge& h) {
  return fmt::format("the edge between {} and {}", at(s, h.low), at(s, h.high));
}

std::size_t check_edges_manifold_and_closed(const QuadSurface& s, const std::vector<HalfEdge>& halves,
                                            const std::string& where) {
  std::size_t edges = 0, boundary = 0;
  const HalfEdge* first_boundary = nullptr;
  for_each_edge(halves, [&](std::size_t i, std::size_t n) {
    ++edges;
    if (n > 2) {
      std::string quads;
      for (std::size_t k = 0; k < n; ++k) quads += fmt::format("{}{}", k ? ", " : "", halves[i + k].quad);
      fail_input(where,
                 fmt::format("non-manifold edge: {} is shared by {} quads ({})", edge_name(s, halves[i]), n, quads),
                 "every edge of a closed surface borders exactly two quads; split the surface there or remove quads");
    }
    if (n == 1 && boundary++ == 0) first_boundary = &halves[i];
  });
  if (boundary > 0)
    fail_input(where,
               fmt::format("open boundary: {} edge{} border only one quad (the first is {}, in quad {})", boundary,
                           boundary == 1 ? "" : "s", edge_name(s, *first_boundary), first_boundary->quad),
               "the surface must be closed; fill the hole(s) with quads");
  return edges;
}

int corner_of(const Quad& q, std::uint32_t node) {
  for (int k = 0; k < 4; ++k)
    if (q[k] == node) return k;
  return -1;
}

// Around a vertex of a closed surface whose edges each border two quads, the
// quads linked through the edges at that vertex form cycles (fans); more than
// one fan means the surface pinches there.
void check_vertices_manifold(const QuadSurface& s, const std::vector<HalfEdge>& halves, const std::string& where) {
  UnionFind corners(4 * s.quads.size());
  for_each_edge(halves, [&](std::size_t i, std::size_t) {
    const HalfEdge &a = halves[i], &b = halves[i + 1];
    for (std::uint32_t node : {a.low, a.high})
      corners.unite(4 * a.quad + corner_of(s.quads[a.quad], node), 4 * b.quad + corner_of(s.quads[b.quad], node));
  });
  std::vector<std::pair<std::uint32_t, std::size_t>> node_fans;  // (node, fan root)
  node_fans.reserve(4 * s.quads.size());
  for (std::size_t c = 0; c < 4 * s.quads.size(); ++c) node_fans.emplace_back(s.quads[c / 4][c % 4], corners.find(c));
  std::sort(node_fans.begin(), node_fans.end());
  node_fans.erase(std::unique(node_fans.begin(), node_fans.end()), node_fans.end());
  for (std::size_t i = 0; i < node_fans.size();) {
    std::size_t j = i + 1;
    while (j < node_fans.size() && node_fans[j].first == node_fans[i].first) ++j;
    if (j - i > 1)
      fail_input(where,
                 fmt::format("non-manifold vertex: the quads around {} form {} separate fans",
                             at(s, node_fans[i].first), j - i),
                 "the surface touches itself at that node; give each part its own copy of the node or remesh there");
    i = j;
  }
}

void check_orientation(const QuadSurface& s, const std::vector<HalfEdge>& halves, const std::string& where) {
  for_each_edge(halves, [&](std::size_t i, std::size_t) {
    const HalfEdge &a = halves[i], &b = halves[i + 1];
    if (a.forward != b.forward) return;
    std::uint32_t from = a.forward ? a.low : a.high, to = a.forward ? a.high : a.low;
    fail_input(where,
               fmt::format("inconsistent orientation: quads {} and {} both run from node {} to node {} along {}",
                           a.quad, b.quad, from, to, edge_name(s, a)),
               "neighbouring quads must traverse their shared edge in opposite directions; reverse the node order of "
               "one of them (or re-orient the whole surface consistently)");
  });
}

void check_single_component(const QuadSurface& s, const std::vector<HalfEdge>& halves, const std::string& where) {
  UnionFind parts(s.quads.size());
  for_each_edge(halves, [&](std::size_t i, std::size_t) { parts.unite(halves[i].quad, halves[i + 1].quad); });
  std::vector<std::size_t> roots;
  for (std::size_t q = 0; q < s.quads.size(); ++q)
    if (parts.find(q) == q) roots.push_back(q);
  if (roots.size() > 1)
    fail_input(where,
               fmt::format("the surface has {} separate components (quad {} is in the first, quad {} in the second)",
                           roots.size(), roots[0], roots[1]),
               "a hex mesh of one solid needs one connected surface; mesh each component separately");
}

void check_even_quad_count(const QuadSurface& s, const std::string& where) {
  if (s.quads.size() % 2 == 0) return;
  fail_input(where,
             fmt::format("{} quads, an odd number: no hex mesh can exist: each chord uses two boundary quads; an odd "
                         "count can never bound a hex mesh",
                         s.quads.size()),
             "subdivide the surface to an even count (splitting every quad into four does)");
}

void check_quads_meet_properly(const QuadSurface& s, const std::string& where) {
  const auto pair = quads_meeting_improperly(s);
  if (!pair) return;
  const Quad &a = s.quads[pair->first], &b = s.quads[pair->second];
  std::vector<std::uint32_t> shared;
  for (std::uint32_t n : a)
    if (std::find(b.begin(), b.end(), n) != b.end()) shared.push_back(n);
  fail_input(where,
             fmt::format("quads {} ({}) and {} ({}) share nodes {} but not as one common edge: the hexes on them "
                         "would meet in a diagonal of one, so no valid hex mesh has this boundary",
                         pair->first, nodes_of(a), pair->second, nodes_of(b), fmt::join(shared, ", ")),
             "refine the surface there (splitting every quad into four parts them)");
}

// Erickson's condition beyond the quad count: every cycle bounding inside the
// solid is even. `outward` says which way the quads face.
void check_meridians_even(const QuadSurface& s, bool outward, const std::string& where, SurfaceSummary& summary) {
  QuadSurface facing_out;
  if (!outward) {
    facing_out = s;
    for (Quad& q : facing_out.quads) std::swap(q[1], q[3]);
  }
  const MeridianReport report = find_meridians(outward ? s : facing_out);
  summary.meridians = report.meridians;
  summary.meridians_known = report.determined;
  if (!report.odd) return;
  fail_input(where,
             fmt::format("no hex mesh can have this boundary: the cycle of nodes {} bounds a surface inside the "
                         "solid and is odd, but every such cycle on a hex mesh's boundary is even",
                         describe_cycle(*report.odd)),
             "make the number of edges round that handle even (splitting every quad into four doubles every cycle)");
}

// Drops nodes no quad uses; returns how many were dropped.
std::size_t drop_unused_nodes(QuadSurface& s) {
  std::vector<std::uint32_t> kept = used_nodes(s);
  const std::size_t dropped = s.points.size() - kept.size();
  if (dropped == 0) return 0;
  std::vector<std::uint32_t> new_index(s.points.size(), 0);
  std::vector<Vec3> points;
  points.reserve(kept.size());
  for (std::uint32_t n : kept) {
    new_index[n] = static_cast<std::uint32_t>(points.size());
    points.push_back(s.points[n]);
  }
  for (Quad& q : s.quads)
    for (std::uint32_t& n : q) n = new_index[n];
  s.points = std::move(points);
  return dropped;
}

// Six times the enclosed volume; quads are split into two triangles, and the
// centroid serves as apex to keep the sum well conditioned far from the origin.
double signed_volume_times_6(const QuadSurface& s) {
  Vec3 centre{0, 0, 0};
  for (const Vec3& p : s.points) centre = centre + p;
  centre = (1.0 / static_cast<double>(s.points.size())) * centre;
  double volume = 0;
  for (const Quad& q : s.quads) {
    Vec3 a = s.points[q[0]] - centre, b = s.points[q[1]] - centre, c = s.points[q[2]] - centre,
         d = s.points[q[3]] - centre;
    volume += dot(a, cross(b, c)) + dot(a, cross(c, d));
  }
  return volume;
}

}  // namespace

SurfaceSummary validate_surface(QuadSurface& surface, const std::string& where, const SurfaceCheckOptions& options) {
  SurfaceSummary summary;
  check_not_empty(surface, where);
  check_finite(surface, where);
  check_quads_well_formed(surface, where, "");
  summary.welded_nodes = handle_coincident_nodes(surface, where, options);
  if (summary.welded_nodes > 0) check_quads_well_formed(surface, where, "after welding, ");

  const std::vector<HalfEdge> halves = half_edges(surface);
  summary.edges = check_edges_manifold_and_closed(surface, halves, where);
  check_vertices_manifold(surface, halves, where);
  check_orientation(surface, halves, where);
  check_single_component(surface, halves, where);
  check_even_quad_count(surface, where);
  check_quads_meet_properly(surface, where);
  const bool outward = signed_volume_times_6(surface) >= 0;
  // A surface of genus 0 has no cycle bounding inside but those bounding on it.
  if (summary.edges != used_nodes(surface).size() + surface.quads.size() - 2)
    check_meridians_even(surface, outward, where, summary);

  summary.unused_nodes = drop_unused_nodes(surface) - summary.welded_nodes;
  if (!outward) {
    for (Quad& q : surface.quads) std::swap(q[1], q[3]);
    summary.flipped = true;
  }
  summary.nodes = surface.points.size();
  summary.quads = surface.quads.size();
  // A closed, connected, orientable surface: V - E + F = 2 - 2g.
  const auto euler = static_cast<long long>(summary.nodes) - static_cast<long long>(summary.edges) +
                     static_cast<long long>(summary.quads);
  summary.genus = static_cast<int>((2 - euler) / 2);
  return summary;
}

std::optional<std::pair<std::size_t, std::size_t>> quads_meeting_improperly(const QuadSurface& s) {
  // Sized by the quads, not the points: randquad asks before it has points.
  std::uint32_t nodes = 0;
  for (const Quad& quad : s.quads)
    for (std::uint32_t n : quad) nodes = std::max(nodes, n + 1);
  std::vector<std::vector<std::uint32_t>> at(nodes);
  for (std::uint32_t q = 0; q < s.quads.size(); ++q)
    for (std::uint32_t n : s.quads[q]) at[n].push_back(q);
  auto corners_of = [&](const Quad& quad, const Quad& other) {
    unsigned mask = 0;
    for (int k = 0; k < 4; ++k)
      if (std::find(other.begin(), other.end(), quad[k]) != other.end()) mask |= 1u << k;
    return mask;
  };
  // Shared corners are fine when they are none, one, or two adjacent ones.
  auto proper = [](unsigned mask) {
    const int count = std::popcount(mask);
    return count <= 1 || (count == 2 && mask != 0b0101 && mask != 0b1010);
  };
  for (std::uint32_t q = 0; q < s.quads.size(); ++q)
    for (std::uint32_t n : s.quads[q])
      for (std::uint32_t other : at[n]) {
        if (other <= q) continue;
        if (!proper(corners_of(s.quads[q], s.quads[other])) || !proper(corners_of(s.quads[other], s.quads[q])))
          return std::pair<std::size_t, std::size_t>{q, other};
      }
  return std::nullopt;
}

}  // namespace loom
