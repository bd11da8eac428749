#pragma once
// Node placement after a weave: interior nodes are moved, boundary nodes never.
#include <vector>

#include "src/mesh/hex_mesh.hpp"

namespace loom::weave {

struct SmoothingReport {
  int iterations = 0;            ///< Laplacian sweeps kept
  double min_before = 0, min_after = 0;  ///< minimum scaled Jacobian
};

/// Laplacian smoothing of the nodes not marked `fixed`: each sweep moves every
/// free node to the mean of its edge neighbours. Up to `max_iterations`
/// sweeps; the positions with the best minimum scaled Jacobian seen are kept
/// (so a mesh that is already optimal, like a structured grid, is unchanged).
SmoothingReport smooth_interior(HexMesh& mesh, const std::vector<bool>& fixed, int max_iterations = 100);

/// Minimum scaled Jacobian over all hexes (1 for an empty mesh).
double min_scaled_jacobian(const HexMesh& mesh);

}  // namespace loom::weave
