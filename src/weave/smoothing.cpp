#include "src/weave/smoothing.hpp"

#include <algorithm>

#include "src/check/validity.hpp"

namespace loom::weave {

double min_scaled_jacobian(const HexMesh& mesh) {
  double m = 1.0;
  for (std::size_t h = 0; h < mesh.hexes.size(); ++h) m = std::min(m, scaled_jacobian(mesh, h));
  return m;
}

SmoothingReport smooth_interior(HexMesh& mesh, const std::vector<bool>& fixed, const SmoothingOptions& options) {
  return geometry::place_nodes(mesh, fixed, options);
}

int laplacian_smooth(HexMesh& mesh, const std::vector<bool>& fixed, int max_iterations) {
  static constexpr int hex_edges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                           {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  std::vector<std::vector<std::uint32_t>> neighbours(mesh.points.size());
  for (const Hex& h : mesh.hexes)
    for (const auto& e : hex_edges) {
      neighbours[h[e[0]]].push_back(h[e[1]]);
      neighbours[h[e[1]]].push_back(h[e[0]]);
    }
  for (auto& n : neighbours) {
    std::sort(n.begin(), n.end());
    n.erase(std::unique(n.begin(), n.end()), n.end());
  }
  double best_min = min_scaled_jacobian(mesh);
  int kept = 0;
  std::vector<Vec3> best = mesh.points, next = mesh.points;
  for (int it = 1; it <= max_iterations && best_min < 1.0; ++it) {
    for (std::size_t p = 0; p < mesh.points.size(); ++p) {
      if (fixed[p] || neighbours[p].empty()) continue;
      Vec3 sum{0, 0, 0};
      for (auto q : neighbours[p]) sum = sum + mesh.points[q];
      next[p] = (1.0 / static_cast<double>(neighbours[p].size())) * sum;
    }
    mesh.points = next;
    const double m = min_scaled_jacobian(mesh);
    if (m > best_min) {
      best_min = m;
      kept = it;
      best = mesh.points;
    }
  }
  mesh.points = best;
  return kept;
}

}  // namespace loom::weave
