#include "src/geometry/placement_detail.hpp"

#include <algorithm>
#include <cmath>

#include "src/check/validity.hpp"

namespace loom::geometry::detail {

int Placer::improve_worst() {
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

bool Placer::improve_node(std::uint32_t p) {
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

}  // namespace loom::geometry::detail
