#pragma once
// The combinatorial choices of the constructive fill (docs/fill.md), made
// once for the whole surface before any hex is built:
//   - the two-colouring of the nodes (a sphere quadrangulation is bipartite);
//   - the even walls: a perfect matching of the quads across edges, so that
//     every quad's cap has exactly one wall of two quads and three of three
//     (what makes each cap's boundary even).
// Each quad's inner diagonal joins its black corners: surface validation
// refuses two quads with the same pair of opposite corners, so no two
// diagonals meet twice.
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
};

/// Plans the fill of a validated surface. Throws loom::InputError when it is
/// not a sphere, not two-colourable, or has no perfect matching (which does
/// not happen on a validated sphere; the message says which).
FillPlan plan_fill(const QuadSurface& surface);

}  // namespace loom::fill
