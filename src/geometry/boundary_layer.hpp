#pragma once
// Pillowing the boundary layer of a hex mesh: one new hex on every boundary
// quad, between the quad and an inner copy of its nodes, so that no hex keeps
// two faces on the boundary. The boundary surface (its nodes, positions and
// quads) is unchanged. docs/geometry.md says when the pipeline does this.
#include <cstddef>
#include <vector>

#include "src/mesh/hex_mesh.hpp"

namespace loom::geometry {

struct BoundaryLayerReport {
  std::size_t hexes_added = 0;  ///< one per boundary quad
  std::size_t nodes_added = 0;  ///< one per boundary node
};

/// Inserts the pillow sheet parallel to the boundary. Every node on a boundary
/// quad gets a copy, placed where it is (placement moves it: the copies are
/// free); the existing hexes use the copies instead, and each boundary quad
/// a b c d, oriented into its hex, gets the hex a b c d a' b' c' d'. `fixed`
/// grows with the copies, marked free. A boundary quad is a hex face that no
/// other hex has. Needs a mesh whose boundary is a closed manifold surface
/// (criteria 1-6): each boundary node must have a single copy.
BoundaryLayerReport pillow_boundary_layer(HexMesh& mesh, std::vector<bool>& fixed);

/// The same for the region of hexes [first, last): a new hex on every quad of
/// the region's boundary (a face no other hex of the region has), the region's
/// hexes moved onto the copies, every other hex left as it is. The new hexes
/// are appended. Afterwards no hex of the region has a node on its boundary,
/// and each new hex meets the boundary in exactly its quad: the region with
/// its pillow meets the rest of the mesh in single faces, edges or nodes of
/// the boundary, whatever the region's hexes did there before.
BoundaryLayerReport pillow_region(HexMesh& mesh, std::size_t first, std::size_t last, std::vector<bool>& fixed);

/// Takes back a layer that pillow_boundary_layer put in as the last `hexes`
/// hexes: those are removed and every copy a' becomes a again in the hexes
/// left (the copies stay as unused nodes). False, and nothing changed, when
/// the last `hexes` hexes are not such a layer.
bool remove_boundary_layer(HexMesh& mesh, std::size_t hexes);

}  // namespace loom::geometry
