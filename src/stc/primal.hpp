#pragma once
// Primal construction: the hex mesh dual to a complete STC.
#include <array>
#include <vector>

#include "src/mesh/hex_mesh.hpp"
#include "src/stc/stc.hpp"

namespace loom::stc {

/// For VTK corner k of a hex, the three hex face slots that meet there.
inline constexpr std::array<std::array<unsigned, 3>, 8> corner_faces{{
    {0, 2, 4}, {0, 2, 5}, {0, 3, 5}, {0, 3, 4}, {1, 2, 4}, {1, 2, 5}, {1, 3, 5}, {1, 3, 4}}};

/// The node at corner k of `hex`: the one node common to its three faces
/// corner_faces[k]; no_element when the hex is degenerate there.
Id corner_node(const Stc& stc, Id hex, unsigned k);

/// Hex connectivity of a complete STC (no whisker left): one point per node in
/// node id order, at stc.points()[node.point]; one hex per STC hex in id order,
/// VTK node order from the hex's face slots. Throws std::runtime_error naming
/// the first hex that is degenerate, a whisker left, or an unplaced node.
/// With `on_boundary`, also says for each point whether its node lies on the
/// boundary surface.
HexMesh to_hex_mesh(const Stc& stc, std::vector<bool>* on_boundary = nullptr);

/// The hexes of a weave in progress: every non-degenerate hex, with the nodes
/// it uses (unplaced nodes at the origin). For inspecting a weave that did not close.
HexMesh woven_hexes(const Stc& stc);

/// The hexes of a weave in progress numbered as the surface it was built from
/// (build_from_surface): points 0..surface_points-1 are the surface's, in
/// order, then one per inner node used (at its position, or the origin while
/// unplaced). A hex that is degenerate or has a node standing for several
/// surface nodes (a through-cell, node.boundary > 1) is left out. With
/// `hexes`, also gives the STC hex of each hex written.
HexMesh woven_over_surface(const Stc& stc, std::size_t surface_points, std::vector<Id>* hexes = nullptr);

}  // namespace loom::stc
