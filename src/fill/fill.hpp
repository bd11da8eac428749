#pragma once
// The constructive fill: a hex mesh of any sphere quadrangulation with an even
// number of quads, built without search (docs/fill.md). What `loom weave` does
// when no weave closes. Under every surface quad sits a cap (src/fill/cap.hpp)
// from the quad to an inner surface, the quad split along a diagonal into two
// triangles each split into three quads; under the inner surface, a cone of
// tetrahedra to one centre node, each split into four hexes.
#include <cstddef>
#include <vector>

#include "src/fill/cap.hpp"
#include "src/mesh/hex_mesh.hpp"
#include "src/mesh/quad_surface.hpp"

namespace loom::fill {

struct FilledMesh {
  HexMesh mesh;                 ///< the surface's nodes first, with their indices
  std::vector<bool> on_boundary;  ///< per node: a surface node (never moved)
  std::size_t cap_hexes = 0, core_hexes = 0;
};

/// Fills a validated, outward-oriented surface with `caps` (load_caps).
/// Nodes get first positions (the inner surface halfway to the centroid,
/// cap nodes from their cap coordinates); placing them is the caller's.
/// Throws loom::InputError when the surface cannot be filled (plan_fill).
FilledMesh fill_constructively(const QuadSurface& surface, const std::vector<Cap>& caps);

}  // namespace loom::fill
