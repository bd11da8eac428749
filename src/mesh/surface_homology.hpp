#pragma once
// The first homology of a closed quad surface over Z/2: a basis of 2g cycles
// and, for every edge, its coordinates in that basis, so that the class of any
// cycle is the sum (XOR) of the coordinates of its edges.
//
// Built by tree-cotree decomposition (Eppstein, SODA 2003): a spanning tree of
// the nodes, a spanning tree of the quads across the remaining edges, and the
// 2g edges in neither, each closing one basis cycle through the tree. The
// coordinates are the dual cocycles: zero on the tree, one on their own
// leftover edge, and on the dual tree whatever makes every quad sum to zero.
// Because every quad has four (an even number of) edges, the parity of a
// cycle's length depends on its class only.
#include <array>
#include <cstdint>
#include <vector>

#include "src/mesh/quad_surface.hpp"

namespace loom {

/// The edges of a surface, numbered, each with its two nodes (smaller first).
struct SurfaceEdges {
  std::vector<std::array<std::uint32_t, 2>> ends;
  std::vector<std::array<std::uint32_t, 4>> of_quad;  ///< edge of quad q from corner k to k + 1
};
SurfaceEdges number_edges(const QuadSurface& surface);
/// The edges at each of `nodes` nodes.
std::vector<std::vector<std::uint32_t>> incident_edges(const SurfaceEdges& edges, std::size_t nodes);

/// A breadth-first spanning tree of the nodes reached from `root`; `parent`
/// and `parent_edge` are UINT32_MAX at the root and at nodes not reached.
struct NodeTree {
  std::vector<std::uint32_t> parent_edge, parent, depth;
  std::vector<std::uint32_t> order;  ///< nodes as reached, the root first
};
NodeTree breadth_first_tree(const SurfaceEdges& edges, const std::vector<std::vector<std::uint32_t>>& incident,
                            std::uint32_t root);
/// The closed walk of edge (a, b) and the tree path from b back to a (nodes;
/// the first not repeated at the end).
std::vector<std::uint32_t> cycle_through(const NodeTree& tree, std::uint32_t a, std::uint32_t b);

/// A homology class over Z/2 as bits in the basis of a SurfaceHomology:
/// bit i of word i / 64.
using HomologyClass = std::vector<std::uint64_t>;

struct SurfaceHomology {
  SurfaceEdges edges;
  /// Each basis cycle as a closed walk of nodes (the first is not repeated at
  /// the end); 2g of them on a connected closed surface of genus g.
  std::vector<std::vector<std::uint32_t>> cycles;
  std::size_t words = 0;  ///< words per class
  /// The class of each edge, `words` words per edge, edge by edge.
  std::vector<std::uint64_t> coordinates;

  std::size_t rank() const { return cycles.size(); }
  const std::uint64_t* class_of_edge(std::size_t edge) const { return coordinates.data() + edge * words; }
};

/// Requires a closed, connected, manifold surface (validate_surface's checks).
SurfaceHomology surface_homology(const QuadSurface& surface);

}  // namespace loom
