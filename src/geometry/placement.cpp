#include "src/geometry/placement.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

#include "src/check/validity.hpp"

namespace loom::geometry {

namespace {

using V3 = Eigen::Vector3d;
using M3 = Eigen::Matrix3d;

/// Verdict's corner edge triples in VTK order (as src/check/scaled_jacobian.cpp):
/// corner k spans the edges to kCornerEdges[k][0..2], positive when right-handed.
constexpr int kCornerEdges[8][3] = {{1, 3, 4}, {2, 0, 5}, {3, 1, 6}, {0, 2, 7},
                                    {7, 5, 0}, {4, 6, 1}, {5, 7, 2}, {6, 4, 3}};
constexpr int kHexEdges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                  {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
constexpr double kInf = std::numeric_limits<double>::infinity();

// Fixed tuning (docs/geometry.md).
constexpr int kNewtonSteps = 1;              // per visit of an unregularised node (delta = 0)
constexpr int kNewtonStepsTangled = 8;       // per visit of a regularised node (delta > 0)
constexpr double kMaxStep = 0.5;             // Newton step cap, in the node's length scale
constexpr int kWorstIterations = 6;          // ascent steps per visit in phase 2
constexpr double kSoftMinBeta = 40.0;        // sharpness of phase 2's soft minimum
constexpr double kSoftMinWindow = 0.25;      // corners this far above the minimum are left out
constexpr double kWorstFirstStep = 0.1;      // phase 2's first trial step, in the node's length scale
constexpr double kWorstMinGain = 1e-3;       // a phase-2 move must raise the local minimum this much
constexpr double kHarmonicTolerance = 1e-8;  // relative residual of the conjugate gradients

V3 to_eigen(const Vec3& p) { return {p[0], p[1], p[2]}; }

/// A corner moved by a free node: corner `corner` of hex `hex`, of which the
/// node is the origin (`col` -1) or the far end of edge `col` (0..2).
struct Entry {
  std::uint32_t hex;
  std::uint8_t corner;
  std::int8_t col;
};

/// Quality summary, in the order the placement is judged by.
struct Summary {
  double min = 1, mean = 1;
  std::size_t below_zero = 0, below_0_2 = 0;
};

/// True when `a` is strictly better than `b`: fewer hexes <= 0, then fewer
/// < 0.2, then a higher minimum, then a higher mean.
bool better(const Summary& a, const Summary& b) {
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
double regularised(double sigma, double delta2, double& r) {
  r = std::sqrt(sigma * sigma + 4.0 * delta2);
  if (sigma >= 0) return 0.5 * (sigma + r);
  return r - sigma > 0 ? 2.0 * delta2 / (r - sigma) : 0.0;
}

/// Scaled Jacobian of a corner at displacement v, and its gradient in v.
double corner_sj(const Local& l, const V3& v, V3* grad) {
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

class Placer {
 public:
  Placer(HexMesh& mesh, const std::vector<bool>& fixed, const PlacementOptions& options)
      : mesh_(mesh), fixed_(fixed), opt_(options) {
    build_topology();
  }

  Summary summarise() const {
    Summary s;
    if (mesh_.hexes.empty()) return s;
    double sum = 0;
    for (std::size_t h = 0; h < mesh_.hexes.size(); ++h) {
      const double q = scaled_jacobian(mesh_, h);
      s.min = std::min(s.min, q);
      sum += q;
      if (q <= 0) ++s.below_zero;
      if (q < 0.2) ++s.below_0_2;
    }
    s.mean = sum / static_cast<double>(mesh_.hexes.size());
    return s;
  }

  /// Hexes whose locked corners (node and three edge ends all fixed, or a
  /// node repeated) have a scaled Jacobian <= 0 (< 0.2): no placement changes those.
  void count_locked(std::size_t& invalid, std::size_t& below_0_2, double& least) const {
    invalid = below_0_2 = 0;
    least = 1;
    for (double bound : locked_bound_) {
      least = std::min(least, bound);
      if (bound <= 0) ++invalid;
      if (bound < 0.2) ++below_0_2;
    }
  }

  /// Moves the free nodes to the solution of the graph Laplace equation on the
  /// hex edges (each free node at the mean of its edge neighbours, the fixed
  /// nodes as Dirichlet data), by Jacobi-preconditioned conjugate gradients
  /// started from the current positions. Returns the iterations.
  int harmonic(int max_iterations) {
    const std::size_t n = mesh_.points.size();
    build_edges();
    std::vector<std::uint32_t> free_nodes;
    for (std::uint32_t p = 0; p < n; ++p)
      if (!fixed_[p] && edge_start_[p] != edge_start_[p + 1]) free_nodes.push_back(p);
    if (free_nodes.empty()) return 0;
    const std::size_t m = free_nodes.size();
    std::vector<std::int64_t> slot(n, -1);
    for (std::size_t i = 0; i < m; ++i) slot[free_nodes[i]] = static_cast<std::int64_t>(i);
    auto degree = [&](std::uint32_t p) { return static_cast<double>(edge_start_[p + 1] - edge_start_[p]); };
    // A = D - adjacency, restricted to the free nodes; the three coordinates
    // are three systems with this matrix, run together with their own steps.
    auto apply_a = [&](const std::vector<V3>& x, std::vector<V3>& y) {
      for (std::size_t i = 0; i < m; ++i) {
        const std::uint32_t p = free_nodes[i];
        V3 acc = degree(p) * x[i];
        for (std::uint32_t e = edge_start_[p]; e < edge_start_[p + 1]; ++e)
          if (const std::int64_t j = slot[edges_[e]]; j >= 0) acc -= x[static_cast<std::size_t>(j)];
        y[i] = acc;
      }
    };
    std::vector<V3> x(m), r(m), z(m), d(m), ad(m);
    for (std::size_t i = 0; i < m; ++i) {
      x[i] = to_eigen(mesh_.points[free_nodes[i]]);
      if (!x[i].allFinite()) x[i].setZero();
    }
    apply_a(x, ad);
    double rhs_norm = 0;
    for (std::size_t i = 0; i < m; ++i) {
      const std::uint32_t p = free_nodes[i];
      V3 b = V3::Zero();
      for (std::uint32_t e = edge_start_[p]; e < edge_start_[p + 1]; ++e)
        if (slot[edges_[e]] < 0) b += to_eigen(mesh_.points[edges_[e]]);
      rhs_norm += b.squaredNorm();
      r[i] = b - ad[i];
    }
    V3 rz = V3::Zero();
    for (std::size_t i = 0; i < m; ++i) {
      z[i] = r[i] / degree(free_nodes[i]);
      d[i] = z[i];
      rz += r[i].cwiseProduct(z[i]);
    }
    const double stop = kHarmonicTolerance * kHarmonicTolerance * std::max(rhs_norm, 1e-300);
    int it = 0;
    for (; it < max_iterations; ++it) {
      double rr = 0;
      for (std::size_t i = 0; i < m; ++i) rr += r[i].squaredNorm();
      if (!(rr > stop)) break;
      apply_a(d, ad);
      V3 dad = V3::Zero();
      for (std::size_t i = 0; i < m; ++i) dad += d[i].cwiseProduct(ad[i]);
      V3 alpha;
      for (int c = 0; c < 3; ++c) alpha[c] = dad[c] > 0 ? rz[c] / dad[c] : 0.0;
      V3 rz_new = V3::Zero();
      for (std::size_t i = 0; i < m; ++i) {
        x[i] += alpha.cwiseProduct(d[i]);
        r[i] -= alpha.cwiseProduct(ad[i]);
        z[i] = r[i] / degree(free_nodes[i]);
        rz_new += r[i].cwiseProduct(z[i]);
      }
      V3 beta;
      for (int c = 0; c < 3; ++c) beta[c] = rz[c] > 0 ? rz_new[c] / rz[c] : 0.0;
      rz = rz_new;
      for (std::size_t i = 0; i < m; ++i) d[i] = z[i] + beta.cwiseProduct(d[i]);
    }
    for (std::size_t i = 0; i < m; ++i)
      if (x[i].allFinite()) mesh_.points[free_nodes[i]] = {x[i][0], x[i][1], x[i][2]};
    return it;
  }

  /// Phase 1: Gauss-Seidel sweeps of local Newton steps on the regularised
  /// energy. Returns the number of sweeps.
  int untangle() {
    std::vector<char> dirty(mesh_.points.size(), 1), next(mesh_.points.size(), 0);
    const double corners = 8.0 * static_cast<double>(mesh_.hexes.size());
    Summary last = summarise();
    int sweeps = 0;
    while (sweeps < opt_.max_untangle_sweeps) {
      ++sweeps;
      update_scales();
      bool moved = false;
      decrease_ = 0;
      regularised_moves_ = 0;
      for (std::uint32_t p = 0; p < mesh_.points.size(); ++p) {
        if (fixed_[p] || !dirty[p] || entry_start_[p] == entry_start_[p + 1]) continue;
        if (untangle_node(p)) {
          moved = true;
          mark_neighbours(p, next);
        }
      }
      if (!moved) break;
      // Go on while the sweep cut the hexes <= 0 or < 0.2, or a tangled
      // node moved, or the energy still fell enough.
      const Summary now = summarise();
      const bool fewer = now.below_zero < last.below_zero || now.below_0_2 < last.below_0_2;
      last = now;
      if (!fewer && regularised_moves_ == 0 && decrease_ < opt_.energy_tolerance * corners) break;
      dirty.swap(next);
      std::fill(next.begin(), next.end(), 0);
    }
    return sweeps;
  }

  /// Phase 2: raise the worst corner around the nodes of hexes below
  /// options.improve_below. Returns the number of sweeps.
  int improve_worst() {
    const std::size_t n = mesh_.points.size();
    std::vector<char> active(n, 0), seen(mesh_.hexes.size(), 0);
    std::vector<std::uint32_t> moved, hexes;
    // Active: the free nodes of each poor hex's worst corner (unless a locked
    // corner bounds that hex as low). First every hex is looked at, then only
    // the hexes of nodes that moved in the last sweep.
    auto activate = [&](std::size_t h) {
      const Hex& hex = mesh_.hexes[h];
      int worst = 0;
      double q = kInf;
      for (int k = 0; k < 8; ++k)
        if (const double c = corner_value(hex, k); c < q) q = c, worst = k;
      if (!(q < opt_.improve_below) || locked_bound_[h] <= q) return;
      const int* e = kCornerEdges[worst];
      for (std::uint32_t v : {hex[worst], hex[e[0]], hex[e[1]], hex[e[2]]})
        if (!fixed_[v]) active[v] = 1;
    };
    for (std::size_t h = 0; h < mesh_.hexes.size(); ++h) activate(h);
    update_scales();
    int sweeps = 0;
    while (sweeps < opt_.max_quality_sweeps) {
      ++sweeps;
      moved.clear();
      for (std::uint32_t p = 0; p < n; ++p) {
        if (!active[p] || entry_start_[p] == entry_start_[p + 1]) continue;
        if (improve_node(p)) moved.push_back(p);
      }
      if (moved.empty()) break;
      // Next sweep: the nodes whose surroundings changed are those of the
      // moved nodes' hexes; look again at every hex holding one of them.
      std::fill(active.begin(), active.end(), 0);
      hexes.clear();
      for (std::uint32_t p : moved)
        for (std::uint32_t i = hex_start_[p]; i < hex_start_[p + 1]; ++i)
          for (std::uint32_t v : mesh_.hexes[node_hexes_[i]])
            for (std::uint32_t j = hex_start_[v]; j < hex_start_[v + 1]; ++j)
              if (const std::uint32_t h = node_hexes_[j]; !seen[h]) seen[h] = 1, hexes.push_back(h);
      for (std::uint32_t h : hexes) {
        seen[h] = 0;
        activate(h);
      }
    }
    return sweeps;
  }

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

  static bool repeats_a_node(const Hex& hex) {
    for (int i = 0; i < 8; ++i)
      for (int j = i + 1; j < 8; ++j)
        if (hex[i] == hex[j]) return true;
    return false;
  }

  void build_topology() {
    const std::size_t n = mesh_.points.size();
    hex_start_.assign(n + 1, 0);
    for (const Hex& h : mesh_.hexes)
      for (std::uint32_t v : h) ++hex_start_[v + 1];
    for (std::size_t i = 0; i < n; ++i) hex_start_[i + 1] += hex_start_[i];
    node_hexes_.resize(hex_start_[n]);
    std::vector<std::uint32_t> fill(hex_start_.begin(), hex_start_.end() - 1);
    for (std::uint32_t h = 0; h < mesh_.hexes.size(); ++h)
      for (std::uint32_t v : mesh_.hexes[h]) node_hexes_[fill[v]++] = h;

    // A hex's locked corners cannot change; a hex with a repeated node is
    // left alone altogether (its scaled Jacobian is -1 wherever its nodes are).
    locked_bound_.assign(mesh_.hexes.size(), kInf);
    for (std::size_t h = 0; h < mesh_.hexes.size(); ++h) {
      const Hex& hex = mesh_.hexes[h];
      if (repeats_a_node(hex)) {
        locked_bound_[h] = -1.0;
        continue;
      }
      for (int k = 0; k < 8; ++k) {
        const int* e = kCornerEdges[k];
        if (fixed_[hex[k]] && fixed_[hex[e[0]]] && fixed_[hex[e[1]]] && fixed_[hex[e[2]]])
          locked_bound_[h] = std::min(locked_bound_[h], corner_value(hex, k));
      }
    }

    // For a free node at corner k of hex h: that corner (the node is its
    // origin) and the three corners joined to it by an edge (it ends one of
    // their edges).
    entry_start_.assign(n + 1, 0);
    for (std::uint32_t p = 0; p < n; ++p) {
      entry_start_[p] = static_cast<std::uint32_t>(entries_.size());
      if (fixed_[p]) continue;
      for (std::uint32_t i = hex_start_[p]; i < hex_start_[p + 1]; ++i) {
        const std::uint32_t h = node_hexes_[i];
        if (repeats_a_node(mesh_.hexes[h])) continue;
        for (int k = 0; k < 8; ++k) {
          if (mesh_.hexes[h][k] != p) continue;
          entries_.push_back({h, static_cast<std::uint8_t>(k), -1});
          for (int j : kCornerEdges[k]) {
            int col = 0;
            while (kCornerEdges[j][col] != k) ++col;
            entries_.push_back({h, static_cast<std::uint8_t>(j), static_cast<std::int8_t>(col)});
          }
        }
      }
    }
    entry_start_[n] = static_cast<std::uint32_t>(entries_.size());
    inv_scale_.assign(mesh_.hexes.size(), 1.0);
  }

  void build_edges() {
    const std::size_t n = mesh_.points.size();
    edge_start_.assign(n + 1, 0);
    edges_.clear();
    std::vector<std::uint32_t> around;
    for (std::uint32_t p = 0; p < n; ++p) {
      around.clear();
      for (std::uint32_t i = hex_start_[p]; i < hex_start_[p + 1]; ++i) {
        const Hex& hex = mesh_.hexes[node_hexes_[i]];
        for (const auto& e : kHexEdges) {
          if (hex[e[0]] == p && hex[e[1]] != p) around.push_back(hex[e[1]]);
          if (hex[e[1]] == p && hex[e[0]] != p) around.push_back(hex[e[0]]);
        }
      }
      std::sort(around.begin(), around.end());
      around.erase(std::unique(around.begin(), around.end()), around.end());
      edge_start_[p] = static_cast<std::uint32_t>(edges_.size());
      edges_.insert(edges_.end(), around.begin(), around.end());
    }
    edge_start_[n] = static_cast<std::uint32_t>(edges_.size());
  }

  /// The scaled Jacobian of corner k of `hex` (-1 when an edge has no length).
  double corner_value(const Hex& hex, int k) const {
    const int* n = kCornerEdges[k];
    const Vec3& p = mesh_.points[hex[k]];
    const Vec3 e1 = mesh_.points[hex[n[0]]] - p, e2 = mesh_.points[hex[n[1]]] - p, e3 = mesh_.points[hex[n[2]]] - p;
    const double l = std::sqrt(dot(e1, e1) * dot(e2, e2) * dot(e3, e3));
    const double q = l > 0 ? dot(e1, cross(e2, e3)) / l : -1.0;
    return std::isfinite(q) ? q : -1.0;
  }

  void update_scales() {
    for (std::size_t h = 0; h < mesh_.hexes.size(); ++h) {
      const Hex& hex = mesh_.hexes[h];
      double sum = 0;
      for (const auto& e : kHexEdges) sum += norm(mesh_.points[hex[e[0]]] - mesh_.points[hex[e[1]]]);
      const double mean = sum / 12.0;
      inv_scale_[h] = mean > 0 && std::isfinite(mean) ? 1.0 / mean : 1.0;
    }
  }

  void mark_neighbours(std::uint32_t p, std::vector<char>& marks) const {
    for (std::uint32_t i = hex_start_[p]; i < hex_start_[p + 1]; ++i)
      for (std::uint32_t v : mesh_.hexes[node_hexes_[i]]) marks[v] = 1;
  }

  /// Fills local_ for node p at its current position; returns the node's
  /// length scale (the mean over its corners of their hexes' mean edge length).
  double gather(std::uint32_t p) {
    local_.clear();
    double scale_sum = 0;
    for (std::uint32_t i = entry_start_[p]; i < entry_start_[p + 1]; ++i) {
      const Entry& en = entries_[i];
      const Hex& hex = mesh_.hexes[en.hex];
      Local l;
      const V3 origin = to_eigen(mesh_.points[hex[en.corner]]);
      for (int c = 0; c < 3; ++c) {
        l.e[c] = to_eigen(mesh_.points[hex[kCornerEdges[en.corner][c]]]) - origin;
        l.c[c] = en.col < 0 ? -1.0 : (en.col == c ? 1.0 : 0.0);
      }
      const V3 cof[3] = {l.e[1].cross(l.e[2]), l.e[2].cross(l.e[0]), l.e[0].cross(l.e[1])};
      l.sigma0 = l.e[0].dot(cof[0]);
      l.f0 = l.e[0].squaredNorm() + l.e[1].squaredNorm() + l.e[2].squaredNorm();
      l.b = l.c[0] * cof[0] + l.c[1] * cof[1] + l.c[2] * cof[2];
      l.gf = 2.0 * (l.c[0] * l.e[0] + l.c[1] * l.e[1] + l.c[2] * l.e[2]);
      l.cc = l.c[0] * l.c[0] + l.c[1] * l.c[1] + l.c[2] * l.c[2];
      l.inv_s = inv_scale_[en.hex];
      l.bound = locked_bound_[en.hex];
      scale_sum += 1.0 / l.inv_s;
      local_.push_back(l);
    }
    return scale_sum / static_cast<double>(local_.size());
  }

  bool apply(std::uint32_t p, const V3& v, double size) {
    if (!v.allFinite() || !(v.norm() > opt_.move_tolerance * size)) return false;
    Vec3& x = mesh_.points[p];
    x = {x[0] + v[0], x[1] + v[1], x[2] + v[2]};
    return true;
  }

  // ---- phase 1 ------------------------------------------------------------
  //
  // Per corner, with A its edge matrix over its hex's scale s, F = |A|_F^2 and
  // sigma = det A: E = (F/3)^(3/2) / h(sigma), i.e. K^(3/2) for K = F / (3
  // h^(2/3)) the regularised inverse mean ratio (1 at a cube corner). The
  // power 3/2 avoids cube roots and weighs poor corners a little more.

  /// The node's energy at displacement v; +inf where some h is 0 (delta = 0
  /// and a corner at or past degenerate: the barrier).
  double energy(const V3& v, double delta2) const {
    double total = 0;
    const double vv = v.squaredNorm();
    for (const Local& l : local_) {
      const double s2 = l.inv_s * l.inv_s, s3 = s2 * l.inv_s;
      const double x = (l.f0 + l.gf.dot(v) + l.cc * vv) * s2 / 3.0;
      double r;
      const double h = regularised((l.sigma0 + l.b.dot(v)) * s3, delta2, r);
      if (!(h > 0)) return kInf;
      total += x * std::sqrt(x) / h;
    }
    return std::isfinite(total) ? total : kInf;
  }

  /// The node's energy at v (as energy()), its gradient and its Hessian.
  double energy_derivatives(const V3& v, double delta2, V3& grad, M3& hess) const {
    grad.setZero();
    hess.setZero();
    double total = 0;
    for (const Local& l : local_) {
      const double s2 = l.inv_s * l.inv_s, s3 = s2 * l.inv_s;
      const double f = (l.f0 + l.gf.dot(v) + l.cc * v.squaredNorm()) * s2;
      const V3 df = (l.gf + 2.0 * l.cc * v) * s2;
      const V3 ds = l.b * s3;
      double r;
      const double h = regularised((l.sigma0 + l.b.dot(v)) * s3, delta2, r);
      const double h1 = h / r, h2 = 2.0 * delta2 / (r * r * r);  // dh/dsigma, d2h/dsigma2
      // E = phi(F) psi(sigma): phi = (F/3)^1.5, psi = 1/h.
      const double x = f / 3.0, rx = std::sqrt(x);
      const double phi = x * rx, phi1 = 0.5 * rx, phi2 = rx > 0 ? 0.25 / (3.0 * rx) : 0.0;
      const double psi = 1.0 / h, psi1 = -h1 / (h * h), psi2 = 2.0 * h1 * h1 / (h * h * h) - h2 / (h * h);
      if (!(h > 0)) return kInf;
      total += phi * psi;
      grad += phi1 * psi * df + phi * psi1 * ds;
      hess += phi2 * psi * df * df.transpose() + (2.0 * l.cc * s2 * phi1 * psi) * M3::Identity() +
              phi1 * psi1 * (df * ds.transpose() + ds * df.transpose()) + phi * psi2 * ds * ds.transpose();
    }
    return std::isfinite(total) ? total : kInf;
  }

  /// Newton steps (Hessian made positive definite by flipping and flooring its
  /// eigenvalues; Armijo backtracking) on the node's energy, with delta^2 =
  /// epsilon (epsilon - sigma_min) when its worst normalised determinant
  /// sigma_min is below epsilon and 0 otherwise.
  bool untangle_node(std::uint32_t p) {
    const double size = gather(p);
    double sigma_min = kInf;
    for (const Local& l : local_) sigma_min = std::min(sigma_min, l.sigma0 * l.inv_s * l.inv_s * l.inv_s);
    const double eps = opt_.epsilon;
    const double delta2 = sigma_min < eps ? eps * (eps - sigma_min) : 0.0;
    V3 v = V3::Zero();
    V3 grad;
    M3 hess;
    double phi = energy_derivatives(v, delta2, grad, hess);
    if (!std::isfinite(phi)) return false;
    const double phi_start = phi;
    const int steps = delta2 > 0 ? kNewtonStepsTangled : kNewtonSteps;
    for (int it = 0; it < steps; ++it) {
      if (it > 0) energy_derivatives(v, delta2, grad, hess);
      if (!grad.allFinite() || !hess.allFinite()) break;
      Eigen::SelfAdjointEigenSolver<M3> eig;
      eig.computeDirect(hess);
      V3 lambda = eig.eigenvalues().cwiseAbs();
      lambda = lambda.cwiseMax(std::max(lambda.maxCoeff() * 1e-6, 1e-12 / (size * size)));
      const M3& q = eig.eigenvectors();
      V3 d = -(q * (q.transpose() * grad).cwiseQuotient(lambda));
      if (!d.allFinite()) break;
      if (d.norm() > kMaxStep * size) d *= kMaxStep * size / d.norm();
      const double slope = grad.dot(d);
      if (!(slope < 0)) break;
      double t = 1.0, trial = kInf;
      for (int ls = 0; ls < 30; ++ls, t *= 0.5) {
        trial = energy(v + t * d, delta2);
        if (trial <= phi + 1e-4 * t * slope) break;
      }
      if (!(trial <= phi + 1e-4 * t * slope)) break;
      v += t * d;
      phi = trial;
      if (t * d.norm() <= opt_.move_tolerance * size) break;
    }
    if (!apply(p, v, size)) return false;
    if (delta2 == 0)
      decrease_ += phi_start - phi;
    else
      ++regularised_moves_;
    return true;
  }

  // ---- phase 2 ------------------------------------------------------------

  /// Raises the least corner value around p, a corner's value being its
  /// scaled Jacobian capped by its hex's locked bound (all that the hex's
  /// scaled Jacobian can gain from it): ascent steps along the gradient of a
  /// soft minimum, each kept only when the true minimum rises and no corner
  /// value crosses 0.2, nor any corner 0, from above.
  bool improve_node(std::uint32_t p) {
    const double size = gather(p);
    const std::size_t n = local_.size();
    q0_.resize(n);
    grads_.resize(n);
    double m = kInf;
    for (std::size_t i = 0; i < n; ++i) {
      q0_[i] = corner_sj(local_[i], V3::Zero(), nullptr);
      m = std::min(m, std::min(q0_[i], local_[i].bound));
    }
    const double start = m;
    V3 v = V3::Zero();
    double step = kWorstFirstStep * size;
    for (int it = 0; it < kWorstIterations; ++it) {
      V3 dir = V3::Zero();
      double wsum = 0;
      for (std::size_t i = 0; i < n; ++i) {
        const double q = corner_sj(local_[i], v, &grads_[i]);
        if (q > m + kSoftMinWindow || q >= local_[i].bound) continue;
        const double w = std::exp(-kSoftMinBeta * (q - m));
        dir += w * grads_[i];
        wsum += w;
      }
      if (!(wsum > 0) || !dir.allFinite() || dir.norm() == 0) break;
      dir.normalize();
      bool accepted = false;
      for (int ls = 0; ls < 12 && !accepted; ++ls, step *= 0.5) {
        const V3 trial = v + step * dir;
        double tm = kInf;
        bool ok = true;
        for (std::size_t i = 0; i < n && ok; ++i) {
          const double q = corner_sj(local_[i], trial, nullptr);
          const double capped = std::min(q, local_[i].bound);
          tm = std::min(tm, capped);
          if ((q0_[i] > 0 && q <= 0) || (std::min(q0_[i], local_[i].bound) >= 0.2 && capped < 0.2)) ok = false;
        }
        if (ok && tm > m + 1e-9) {
          v = trial;
          m = tm;
          accepted = true;
        }
      }
      if (!accepted) break;
      step *= 4.0;  // undo the last halving and try a longer step next
    }
    if (!(m > start + kWorstMinGain)) return false;
    return apply(p, v, size);
  }
};

}  // namespace

PlacementReport place_nodes(HexMesh& mesh, const std::vector<bool>& fixed, const PlacementOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  if (fixed.size() != mesh.points.size())
    throw std::invalid_argument("place_nodes: " + std::to_string(fixed.size()) + " fixed flags for " +
                                std::to_string(mesh.points.size()) + " nodes");
  for (const Hex& h : mesh.hexes)
    for (std::uint32_t v : h)
      if (v >= mesh.points.size()) throw std::invalid_argument("place_nodes: a hex refers to a node out of range");

  PlacementReport report;
  Placer placer(mesh, fixed, options);
  const Summary before = placer.summarise();
  placer.count_locked(report.locked_invalid, report.locked_below_0_2, report.locked_min);
  Summary result = before;
  if (mesh.hexes.empty() || before.min >= options.improve_below) {
    report.skipped = true;
  } else {
    const std::vector<Vec3> original = mesh.points;
    const bool tangled = before.below_zero > report.locked_invalid;
    if (options.start == PlacementOptions::Start::harmonic ||
        (options.start == PlacementOptions::Start::harmonic_when_tangled && tangled))
      report.harmonic_iterations = placer.harmonic(options.max_harmonic_iterations);
    report.untangle_sweeps = placer.untangle();
    if (!better(placer.summarise(), before)) mesh.points = original;  // phase 2 starts from the input
    report.quality_sweeps = placer.improve_worst();
    result = placer.summarise();
    if (better(result, before)) {
      report.changed = true;
    } else {
      mesh.points = original;
      result = before;
    }
  }
  report.iterations = report.untangle_sweeps + report.quality_sweeps;
  report.min_before = before.min;
  report.mean_before = before.mean;
  report.below_zero_before = before.below_zero;
  report.below_0_2_before = before.below_0_2;
  report.min_after = result.min;
  report.mean_after = result.mean;
  report.below_zero_after = result.below_zero;
  report.below_0_2_after = result.below_0_2;
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace loom::geometry
