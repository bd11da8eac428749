#pragma once
// The boundary of a hex mesh as a quad surface.
#include <cstdint>
#include <vector>

#include "src/mesh/hex_mesh.hpp"
#include "src/mesh/quad_surface.hpp"

namespace loom {

/// The faces held by exactly one hex, oriented as that hex sees them from
/// outside (outward for a positively oriented mesh), in order of (hex, local
/// face). Nodes are renumbered in order of first use; `mesh_node`, when given,
/// receives each surface node's index in the mesh. Precondition: criterion 1.
QuadSurface hex_mesh_boundary(const HexMesh& mesh, std::vector<std::uint32_t>* mesh_node = nullptr);

}  // namespace loom
