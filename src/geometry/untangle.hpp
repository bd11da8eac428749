#pragma once
// Global untangling of the free nodes of a hex mesh, by the method of
// Garanzha, Kaporin, Kudryavtseva, Protais, Ray and Sokolov ("Foldover-free
// maps in 50 lines of code", ACM TOG 2021), on the nine Jacobian frames of
// each hex that criterion 7 measures (its 8 corner tetrahedra and its centre,
// as Verdict does). With J a frame's matrix over a reference length h, each
// frame costs
//     tr(J^T J) / chi(det J)^(2/3) + lambda (det(J)^2 + 1) / chi(det J),
//     chi(D) = (D + sqrt(eps^2 + D^2)) / 2,
// which is smooth for every eps > 0 and, as eps goes to 0, a barrier against
// frames with det J <= 0. All free nodes move at once (L-BFGS, LBFGSpp);
// eps falls, round after round, as the minimum frame rises. It unties what
// moving one node at a time (placement.hpp, phase 1) cannot: a fold whose
// nodes must all move together. Fixed nodes are never written.
#include <cstddef>
#include <vector>

#include "src/mesh/hex_mesh.hpp"

namespace loom::geometry {

struct UntangleOptions {
  int max_rounds = 500;       ///< eps updates
  int max_iterations = 200;   ///< L-BFGS iterations a round
  double lambda = 1.0;        ///< weight of the volume term against the shape term
  int patience = 50;          ///< rounds without fewer inverted hexes before giving up
};

struct UntangleReport {
  /// Hexes with a frame of determinant <= 0 (scaled Jacobian <= 0), before
  /// and after; locked ones (every node of the frame fixed) included.
  std::size_t inverted_before = 0, inverted_after = 0;
  int rounds = 0, iterations = 0;
  bool untangled = false;  ///< no hex is inverted but those with a locked inverted frame
  double seconds = 0;
};

/// Moves the nodes with fixed[i] == false until no frame with a free node
/// is inverted, or the rounds run out; the positions with the fewest inverted
/// hexes seen are kept. Deterministic.
UntangleReport untangle(HexMesh& mesh, const std::vector<bool>& fixed, const UntangleOptions& options = {});

}  // namespace loom::geometry
