#pragma once
// How many hexes stand round each edge of a hex mesh, and which edges and
// nodes lie on its boundary: the valence whose distance from the ideal (4
// inside, 2 on a flat boundary) says how irregular a mesh is (issue 32,
// "reporting"), and what the inversion diagnosis and the depth count from.
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <vector>

#include "src/check/hex_topology.hpp"

namespace loom {

struct EdgeValences {
  std::vector<std::uint32_t> hexes_round;  ///< per edge of the topology: hexes that hold it
  std::vector<bool> on_boundary;           ///< per edge: it is a side of a boundary face
  std::vector<bool> node_on_boundary;      ///< per mesh point: a corner of a boundary face
};

/// An interior edge's distance from valence 4 with `hexes` round it: |hexes -
/// 4| once it is closed, the hexes beyond 4 while it is open (they can only
/// gain more). What the weave's `irregular` and the closure search's cost sum.
inline int edge_irregularity(int hexes, bool closed) { return closed ? std::abs(hexes - 4) : std::max(0, hexes - 4); }

/// Precondition: as build_hex_topology's, and `topo` is `mesh`'s.
EdgeValences edge_valences(const HexMesh& mesh, const HexTopology& topo);

/// Interior edges by valence: {valence: edges}. Empty when the mesh's hexes do
/// not have 8 distinct nodes each (no topology to count on).
std::map<std::uint32_t, std::size_t> interior_valence_histogram(const HexMesh& mesh);

}  // namespace loom
