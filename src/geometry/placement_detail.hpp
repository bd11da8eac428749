#pragma once
// Internals of node placement (placement.hpp): the corner bookkeeping, the
// per-node energies and the Placer, whose phases live in placement.cpp
// (topology, summaries), placement_harmonic.cpp (step 0),
// placement_untangle.cpp (phase 1) and placement_worst.cpp (phase 2).
#include <Eigen/Dense>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "src/check/hex_topology.hpp"
#include "src/geometry/placement.hpp"

namespace loom::geometry::detail {


using V3 = Eigen::Vector3d;
using M3 = Eigen::Matrix3d;

/// Verdict's corner edge triples in VTK order (as src/check/scaled_jacobian.cpp):
/// corner k spans the edges to kCornerEdges[k][0..2], positive when right-handed.
inline constexpr int kCornerEdges[8][3] = {{1, 3, 4}, {2, 0, 5}, {3, 1, 6}, {0, 2, 7},
                                    {7, 5, 0}, {4, 6, 1}, {5, 7, 2}, {6, 4, 3}};
inline constexpr double kInf = std::numeric_limits<double>::infinity();

// Fixed tuning (docs/geometry.md).
inline constexpr int kNewtonSteps = 1;              // per visit of an unregularised node (delta = 0)
inline constexpr int kNewtonStepsTangled = 8;       // per visit of a regularised node (delta > 0)
inline constexpr double kMaxStep = 0.5;             // Newton step cap, in the node's length scale
inline constexpr int kWorstIterations = 6;          // ascent steps per visit in phase 2
inline constexpr double kSoftMinBeta = 40.0;        // sharpness of phase 2's soft minimum
inline constexpr double kSoftMinWindow = 0.25;      // corners this far above the minimum are left out
inline constexpr double kWorstFirstStep = 0.1;      // phase 2's first trial step, in the node's length scale
inline constexpr double kWorstMinGain = 1e-3;       // a phase-2 move must raise the local minimum this much
inline constexpr double kHarmonicTolerance = 1e-8;  // relative residual of the conjugate gradients

inline V3 to_eigen(const Vec3& p) { return {p[0], p[1], p[2]}; }

/// A corner moved by a free node: corner `corner` of hex `hex`, of which the
/// node is the origin (`col` -1) or the far end of edge `col` (0..2).
struct Entry {
  std::uint32_t hex;
  std::uint8_t corner;
  std::int8_t col;
};

/// Quality summary, in the order the placement is judged by, with Verdict's
/// measure (corners and centre; placement.cpp).
struct Summary {
  double min = 1, mean = 1;
  std::size_t below_zero = 0, below_0_2 = 0;
};

/// True when `a` is strictly better than `b`: fewer hexes <= 0, then fewer
/// < 0.2, then a higher minimum, then a higher mean.
inline bool better(const Summary& a, const Summary& b) {
  if (a.below_zero != b.below_zero) return a.below_zero < b.below_zero;
  if (a.below_0_2 != b.below_0_2) return a.below_0_2 < b.below_0_2;
  if (a.min != b.min) return a.min > b.min;
  return a.mean > b.mean;
}

/// One corner around the node being placed, at the node's current position,
/// and how it changes with the node's displacement v: edge i is e[i] + c[i] v
/// (c = -1 for all three when the node is the corner's origin, else 1 for the
/// one edge that ends at the node). The corner's determinant is then affine
/// in v, sigma0 + b.v (a rank-one update), and its squared Frobenius norm
/// quadratic, f0 + gf.v + cc |v|^2: both are exact for any v.
struct Local {
  V3 e[3];
  double c[3];
  double sigma0, f0, cc;
  V3 b, gf;
  double inv_s;  // 1 / the hex's mean edge length (frozen for the sweep)
  double bound;  // the hex's locked bound (inf: none)
};

/// h(sigma) = (sigma + sqrt(sigma^2 + 4 delta^2)) / 2 without cancellation;
/// r receives sqrt(sigma^2 + 4 delta^2).
inline double regularised(double sigma, double delta2, double& r) {
  r = std::sqrt(sigma * sigma + 4.0 * delta2);
  if (sigma >= 0) return 0.5 * (sigma + r);
  return r - sigma > 0 ? 2.0 * delta2 / (r - sigma) : 0.0;
}

/// Scaled Jacobian of a corner at displacement v, and its gradient in v.
inline double corner_sj(const Local& l, const V3& v, V3* grad) {
  V3 e[3];
  double len2[3];
  for (int c = 0; c < 3; ++c) {
    e[c] = l.e[c] + l.c[c] * v;
    len2[c] = e[c].squaredNorm();
  }
  const double prod = len2[0] * len2[1] * len2[2];
  if (!(prod > 0) || !std::isfinite(prod)) return -1.0;
  const double len = std::sqrt(prod);
  const double q = (l.sigma0 + l.b.dot(v)) / len;
  if (grad) *grad = l.b / len - q * (l.c[0] * e[0] / len2[0] + l.c[1] * e[1] / len2[1] + l.c[2] * e[2] / len2[2]);
  return q;
}

/// Places the free nodes of one mesh: the topology (corners per node, edges)
/// is built once, then each phase sweeps over the nodes.
class Placer {
 public:
  Placer(HexMesh& mesh, const std::vector<bool>& fixed, const PlacementOptions& options)
      : mesh_(mesh), fixed_(fixed), opt_(options) {
    build_topology();
  }

  Summary summarise() const;

  /// Hexes whose locked corners (node and three edge ends all fixed, or a
  /// node repeated) have a scaled Jacobian <= 0 (< 0.2): no placement changes those.
  void count_locked(std::size_t& invalid, std::size_t& below_0_2, double& least) const;

  /// Moves the free nodes to the solution of the graph Laplace equation on the
  /// hex edges (each free node at the mean of its edge neighbours, the fixed
  /// nodes as Dirichlet data), by Jacobi-preconditioned conjugate gradients
  /// started from the current positions. Returns the iterations.
  int harmonic(int max_iterations);

  /// Phase 1: Gauss-Seidel sweeps of local Newton steps on the regularised
  /// energy. Returns the number of sweeps.
  int untangle();

  /// Phase 2: raise the worst corner around the nodes of hexes below
  /// options.improve_below. Returns the number of sweeps.
  int improve_worst();

 private:
  HexMesh& mesh_;
  const std::vector<bool>& fixed_;
  PlacementOptions opt_;
  std::vector<std::uint32_t> entry_start_;  // per node, into entries_
  std::vector<Entry> entries_;
  std::vector<std::uint32_t> hex_start_;  // per node, into node_hexes_
  std::vector<std::uint32_t> node_hexes_;
  std::vector<std::uint32_t> edge_start_, edges_;  // per node, its edge neighbours
  std::vector<double> inv_scale_;                  // per hex: 1 / mean edge length
  std::vector<double> locked_bound_;               // per hex: least scaled Jacobian of its locked corners (inf: none)
  std::vector<Local> local_;                       // the corners around the node being placed
  std::vector<double> q0_;                         // phase 2: their scaled Jacobians at the start of the visit
  std::vector<V3> grads_;                          // phase 2: their gradients
  double decrease_ = 0;                            // energy decrease of unregularised nodes in this sweep
  std::size_t regularised_moves_ = 0;              // moves of regularised nodes (delta > 0) in this sweep

  static bool repeats_a_node(const Hex& hex);

  void build_topology();

  void build_edges();

  /// The scaled Jacobian of corner k of `hex` (-1 when an edge has no length).
  double corner_value(const Hex& hex, int k) const;

  void update_scales();

  void mark_neighbours(std::uint32_t p, std::vector<char>& marks) const;

  /// Fills local_ for node p at its current position; returns the node's
  /// length scale (the mean over its corners of their hexes' mean edge length).
  double gather(std::uint32_t p);

  bool apply(std::uint32_t p, const V3& v, double size);

  // ---- phase 1 ------------------------------------------------------------
  //
  // Per corner, with A its edge matrix over its hex's scale s, F = |A|_F^2 and
  // sigma = det A: E = (F/3)^(3/2) / h(sigma), i.e. K^(3/2) for K = F / (3
  // h^(2/3)) the regularised inverse mean ratio (1 at a cube corner). The
  // power 3/2 avoids cube roots and weighs poor corners a little more.

  /// The node's energy at displacement v; +inf where some h is 0 (delta = 0
  /// and a corner at or past degenerate: the barrier).
  double energy(const V3& v, double delta2) const;

  /// The node's energy at v (as energy()), its gradient and its Hessian.
  double energy_derivatives(const V3& v, double delta2, V3& grad, M3& hess) const;

  /// Newton steps (Hessian made positive definite by flipping and flooring its
  /// eigenvalues; Armijo backtracking) on the node's energy, with delta^2 =
  /// epsilon (epsilon - sigma_min) when its worst normalised determinant
  /// sigma_min is below epsilon and 0 otherwise.
  bool untangle_node(std::uint32_t p);

  // ---- phase 2 ------------------------------------------------------------

  /// Raises the least corner value around p, a corner's value being its
  /// scaled Jacobian capped by its hex's locked bound (all that the hex's
  /// scaled Jacobian can gain from it): ascent steps along the gradient of a
  /// soft minimum, each kept only when the true minimum rises and no corner
  /// value crosses 0.2, nor any corner 0, from above.
  bool improve_node(std::uint32_t p);
};

}  // namespace loom::geometry::detail
