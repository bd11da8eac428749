#pragma once
// Node placement for a hex mesh whose boundary nodes are fixed: untangling and
// quality smoothing of the free (interior) nodes. docs/geometry.md has the
// method, the stopping rules and the figures.
//
//  0. start: when the input has a hex <= 0 that placement can fix, the free
//     nodes first go to the harmonic placement (graph Laplace equation on the
//     hex edges, fixed nodes as data; conjugate gradients);
//  1. untangle + shape: Gauss-Seidel sweeps over the free nodes in index
//     order, each node minimising alone the sum over the hex corners it moves
//     of a regularised inverse mean ratio (Escobar et al.'s simultaneous
//     untangling and smoothing), by Newton steps with a line search;
//  2. worst corner: sweeps over the nodes of the worst corners of hexes below
//     `improve_below`, each raising the least scaled Jacobian around it
//     without pushing any corner across 0 or 0.2 from above;
//  3. when hexes <= 0 are left that are not locked: all free nodes moved at
//     once (untangle.hpp), then phase 2 again, kept when better.
// Sequential and deterministic. Fixed nodes are never written.
#include <cstddef>
#include <vector>

#include "src/mesh/hex_mesh.hpp"

namespace loom::geometry {

struct PlacementOptions {
  /// Nothing is done when every hex's scaled Jacobian is at least this; phase 2
  /// works on hexes below it.
  double improve_below = 0.5;
  /// When to start from the harmonic placement instead of the input positions.
  enum class Start { input, harmonic_when_tangled, harmonic };
  Start start = Start::harmonic_when_tangled;
  int max_harmonic_iterations = 2000;
  /// Sweep caps of the two phases.
  int max_untangle_sweeps = 100;
  int max_quality_sweeps = 100;
  /// Regularisation of phase 1: a node whose worst corner has a normalised
  /// determinant sigma (det / s^3, s its hex's mean edge length; 1 for a cube)
  /// below epsilon gets delta^2 = epsilon (epsilon - sigma), which makes that
  /// corner's regularised determinant exactly epsilon; at or above epsilon,
  /// delta = 0 and the energy is a barrier against degenerate corners.
  double epsilon = 0.01;
  /// A node moves only by more than this times its length scale (the mean
  /// edge length of its hexes); only nodes near moved nodes are revisited.
  double move_tolerance = 1e-3;
  /// Phase 1 stops when no regularised node moved and the sweep lowered the
  /// energy by less than this per hex corner (a cube corner's energy is 1).
  double energy_tolerance = 1e-3;
};

struct PlacementReport {
  int iterations = 0;           ///< sweeps done, both phases
  int harmonic_iterations = 0;  ///< conjugate-gradient iterations of the start (0: input start)
  int untangle_sweeps = 0, quality_sweeps = 0;
  /// Rounds of the global untangling (untangle.hpp), run when phases 1 and 2
  /// leave hexes <= 0 that are not locked (0: not run).
  int global_rounds = 0;
  // The figures below take each hex's corners and its centre (Verdict's
  // measure), which placement is judged by; criterion 7 takes the corners only.
  double min_before = 0, min_after = 0;                     ///< minimum scaled Jacobian
  double mean_before = 0, mean_after = 0;                   ///< mean scaled Jacobian
  std::size_t below_zero_before = 0, below_zero_after = 0;  ///< hexes <= 0
  std::size_t below_0_2_before = 0, below_0_2_after = 0;    ///< hexes < 0.2
  /// Hexes with a locked corner (the corner's node and its three edge
  /// neighbours all fixed): no placement changes that corner, so its scaled
  /// Jacobian bounds the hex's. `locked_invalid` counts those with a locked
  /// corner <= 0, `locked_below_0_2` those with one < 0.2 (floors for
  /// below_zero_after and below_0_2_after).
  std::size_t locked_invalid = 0, locked_below_0_2 = 0;
  /// The least locked corner (1 when there is none): a bound on min_after.
  double locked_min = 1;
  bool skipped = false;  ///< nothing to do: no hexes, or min >= improve_below
  bool changed = false;  ///< the nodes were moved (false: bit-identical)
  double seconds = 0;
};

struct LockedCorners {
  std::size_t invalid = 0;    ///< hexes with a locked corner <= 0
  std::size_t below_0_2 = 0;  ///< hexes with a locked corner < 0.2
  double least = 1;           ///< the least locked corner (1 when there is none)
};

/// The locked corners of a mesh (see PlacementReport::locked_invalid): what no
/// placement of the free nodes can change. Same preconditions as place_nodes.
LockedCorners locked_corners(const HexMesh& mesh, const std::vector<bool>& fixed);

/// Moves the nodes with fixed[i] == false to untangle the mesh and raise its
/// scaled Jacobians. The result replaces the input only when it is better:
/// fewer hexes <= 0, then fewer < 0.2, then a higher minimum, then a higher
/// mean; otherwise the mesh is left bit-identical. Linear work per sweep.
/// Throws std::invalid_argument when fixed.size() != mesh.points.size() or a
/// hex refers to a node out of range.
PlacementReport place_nodes(HexMesh& mesh, const std::vector<bool>& fixed, const PlacementOptions& options = {});

}  // namespace loom::geometry
