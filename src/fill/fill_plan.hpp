#pragma once
// The combinatorial choices of the constructive fill (docs/fill.md), made
// once for the whole surface before any hex is built:
//   - the two-colouring of the nodes (a sphere quadrangulation is bipartite);
//   - the even walls: a perfect matching of the quads across edges, so that
//     every quad's cap has exactly one wall of two quads and three of three
//     (what makes each cap's boundary even);
//   - each quad's inner diagonal, so that no two quads put a diagonal on the
//     same pair of nodes (a 2-SAT problem).
#include <array>
#include <cstdint>
#include <vector>

#include "src/mesh/quad_surface.hpp"

namespace loom::fill {

struct FillPlan {
  std::vector<bool> white;                               ///< per node: its colour
  std::vector<std::array<std::uint32_t, 2>> edge_nodes;  ///< per edge
  std::vector<std::array<std::uint32_t, 4>> quad_edges;  ///< per quad: edge of side k (corner k to k+1)
  std::vector<bool> even_edge;                           ///< per edge: in the matching
  std::vector<std::uint32_t> mate;                       ///< per quad: the quad across its even edge
  std::vector<bool> black_diagonal;                      ///< per quad: its diagonal joins its black corners
};

/// Throws loom::InputError when the surface is not a sphere, is not
/// two-colourable, or has no perfect matching or diagonal choice (neither
/// happens on a sphere without repeated edges; the message says which).
FillPlan plan_fill(const QuadSurface& surface);

}  // namespace loom::fill
