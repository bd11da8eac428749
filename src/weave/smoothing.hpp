#pragma once
// Node placement after a weave: interior nodes are moved, boundary nodes never
// (docs/geometry.md). The work is done by src/geometry/placement.hpp.
#include <vector>

#include "src/geometry/placement.hpp"
#include "src/mesh/hex_mesh.hpp"

namespace loom::weave {

using SmoothingReport = geometry::PlacementReport;
using SmoothingOptions = geometry::PlacementOptions;

/// Untangles and smooths the nodes not marked `fixed` (geometry::place_nodes):
/// the mesh is changed only when that makes it better (fewer hexes with scaled
/// Jacobian <= 0, then fewer below 0.2, then a higher minimum, then a higher
/// mean), so a mesh that is already good, like a structured grid, is unchanged.
SmoothingReport smooth_interior(HexMesh& mesh, const std::vector<bool>& fixed, const SmoothingOptions& options = {});

/// Plain Laplacian smoothing of the free nodes: up to `max_iterations` Jacobi
/// sweeps moving each to the mean of its edge neighbours; the positions with
/// the best minimum scaled Jacobian seen are kept. Returns the sweeps kept.
int laplacian_smooth(HexMesh& mesh, const std::vector<bool>& fixed, int max_iterations = 100);

/// Minimum scaled Jacobian over all hexes (1 for an empty mesh).
double min_scaled_jacobian(const HexMesh& mesh);

}  // namespace loom::weave
