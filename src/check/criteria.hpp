#pragma once
// The criteria of docs/validity.md, one function each. check_hex_mesh()
// (validity.cpp) runs them in order; 2-6 need criterion 1 to hold, since the
// topology is built from hexes with 8 distinct in-range nodes.
#include <fmt/format.h>

#include "src/check/hex_topology.hpp"
#include "src/check/validity.hpp"

namespace loom::criteria {

/// A passed result for `number`, named.
CriterionResult passed(int number);
/// A failed result for `number` with `detail`.
CriterionResult failed(int number, std::string detail);

/// 1: every hex has 8 distinct nodes, each an index into the mesh's points.
CriterionResult distinct_nodes(const HexMesh& mesh);
/// 2: no duplicated hexes (same node set), and every face in one or two hexes.
CriterionResult faces_in_one_or_two_hexes(const HexMesh& mesh, const HexTopology& topo);
/// 3: no two hexes share more than one face (no doublets), and more generally
/// any two hexes meet in one face, one edge, one node or not at all (the
/// validity of Verhetsel et al. 2019).
CriterionResult no_doublets(const HexMesh& mesh, const HexTopology& topo);
/// The second half of criterion 3, on its own.
CriterionResult hexes_meet_properly(const HexMesh& mesh);
/// 4: edge links are one cycle or one fan; node links are spheres or disks.
CriterionResult manifold(const HexMesh& mesh, const HexTopology& topo);

struct BoundaryShape {
  std::size_t components = 0;
  int genus = 0;  ///< summed over the boundary's components
};
/// 5: one connected solid with V - E + F - C = sum over boundary components of
/// (1 - genus), i.e. 1 for a ball. Fills `shape`.
CriterionResult euler_characteristic(const HexMesh& mesh, const HexTopology& topo, BoundaryShape& shape);
/// 6: the boundary faces are exactly the quads of `surface`.
CriterionResult boundary_matches(const HexMesh& mesh, const HexTopology& topo, const QuadSurface& surface);
/// 7: every hex has a positive scaled Jacobian. Fills `quality`.
CriterionResult positive_scaled_jacobian(const HexMesh& mesh, QualitySummary& quality);

}  // namespace loom::criteria
