#include "src/geometry/placement_detail.hpp"

#include <algorithm>
#include <cmath>

#include "src/check/validity.hpp"

namespace loom::geometry::detail {

int Placer::harmonic(int max_iterations) {
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

}  // namespace loom::geometry::detail
