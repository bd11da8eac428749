#pragma once
// Building the STC: from a hex mesh (its full dual) or from a quad surface
// (the initial weave state: every boundary face a whisker, sheets = loops).
#include "src/mesh/hex_mesh.hpp"
#include "src/mesh/quad_surface.hpp"
#include "src/stc/stc.hpp"

namespace loom::stc {

/// The dual of a hex mesh: one hex per cell (hex.source = its index), one node
/// per used point (in point order), faces and edges deduplicated, sheets as the
/// classes of parallel edges, chords as the classes of opposite faces, boundary
/// faces numbered in face order. Self-intersecting sheets and chords are
/// flagged. Throws InputError if a face is shared by more than two hexes or a
/// hex repeats a node.
Stc build_from_hex_mesh(const HexMesh& mesh);

/// The initial weave state of a validated, outward-oriented quad surface:
/// nodes, edges and faces of the surface (face.boundary = quad index), no hex,
/// one loop (sheet) per class of opposite edges, one whisker chord per face on
/// the face's two loops. Loops that cross themselves are flagged.
Stc build_from_surface(const QuadSurface& surface);

}  // namespace loom::stc
