#include "src/check/depth.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>

#include "src/check/criteria.hpp"
#include "src/check/edge_valence.hpp"
#include "src/check/hex_topology.hpp"
#include "src/check/validity.hpp"

namespace loom {

DepthProfile depth_profile(const HexMesh& mesh) {
  DepthProfile profile;
  if (mesh.hexes.empty() || !criteria::distinct_nodes(mesh).passed) return profile;
  const HexTopology topo = build_hex_topology(mesh);
  constexpr std::size_t unreached = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> depth(mesh.points.size(), unreached);
  std::deque<std::uint32_t> queue;
  const std::vector<bool> on_boundary = edge_valences(mesh, topo).node_on_boundary;
  for (std::uint32_t v = 0; v < on_boundary.size(); ++v)
    if (on_boundary[v]) depth[v] = 0, queue.push_back(v);
  std::vector<std::vector<std::uint32_t>> neighbours(mesh.points.size());
  for (const Hex& hex : mesh.hexes)
    for (const auto& [a, b] : kHexEdgeCorners) {
      neighbours[hex[static_cast<std::size_t>(a)]].push_back(hex[static_cast<std::size_t>(b)]);
      neighbours[hex[static_cast<std::size_t>(b)]].push_back(hex[static_cast<std::size_t>(a)]);
    }
  while (!queue.empty()) {
    const std::uint32_t v = queue.front();
    queue.pop_front();
    for (std::uint32_t w : neighbours[v])
      if (depth[w] == unreached) depth[w] = depth[v] + 1, queue.push_back(w);
  }
  for (std::size_t h = 0; h < mesh.hexes.size(); ++h) {
    std::size_t d = 0;
    for (std::uint32_t v : mesh.hexes[h]) d = std::max(d, depth[v] == unreached ? 0 : depth[v]);
    d = std::max<std::size_t>(d, 1);
    if (profile.hexes.size() <= d) profile.hexes.resize(d + 1, 0), profile.inverted.resize(d + 1, 0);
    ++profile.hexes[d];
    profile.inverted[d] += !(scaled_jacobian(mesh, h) > 0);
  }
  return profile;
}

namespace {

/// The distance along the ray `from + t dir` (t > 0) to triangle a b c, or infinity (Moller-Trumbore).
double ray_triangle(const Vec3& from, const Vec3& dir, const Vec3& a, const Vec3& b, const Vec3& c) {
  constexpr double none = std::numeric_limits<double>::infinity();
  const Vec3 e1 = b - a, e2 = c - a, p = cross(dir, e2);
  const double det = dot(e1, p);
  if (std::abs(det) < 1e-300) return none;
  const Vec3 s = from - a;
  const double u = dot(s, p) / det;
  if (u < 0 || u > 1) return none;
  const Vec3 q = cross(s, e1);
  const double v = dot(dir, q) / det;
  if (v < 0 || u + v > 1) return none;
  const double t = dot(e2, q) / det;
  return t > 0 ? t : none;
}

}  // namespace

SurfaceThickness surface_half_thickness(const QuadSurface& surface, std::size_t max_rays) {
  SurfaceThickness out;
  const auto& P = surface.points;
  if (surface.quads.empty() || max_rays == 0) return out;
  double edge = 0;
  for (const Quad& q : surface.quads)
    for (std::size_t i = 0; i < 4; ++i) edge += norm(P[q[(i + 1) % 4]] - P[q[i]]);
  edge /= 4.0 * static_cast<double>(surface.quads.size());
  if (!(edge > 0)) return out;
  const std::size_t stride = (surface.quads.size() + max_rays - 1) / max_rays;
  std::vector<double> halves;
  for (std::size_t k = 0; k < surface.quads.size(); k += stride) {
    const Quad& q = surface.quads[k];
    const Vec3 centre = 0.25 * (P[q[0]] + P[q[1]] + P[q[2]] + P[q[3]]);
    const Vec3 outward = cross(P[q[2]] - P[q[0]], P[q[3]] - P[q[1]]);
    if (!(norm(outward) > 0)) continue;
    const Vec3 inward = (-1.0 / norm(outward)) * outward;
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < surface.quads.size(); ++j) {
      if (j == k) continue;
      const Quad& o = surface.quads[j];
      nearest = std::min({nearest, ray_triangle(centre, inward, P[o[0]], P[o[1]], P[o[2]]),
                          ray_triangle(centre, inward, P[o[0]], P[o[2]], P[o[3]])});
    }
    if (std::isfinite(nearest)) halves.push_back(0.5 * nearest / edge);
  }
  if (halves.empty()) return out;
  std::sort(halves.begin(), halves.end());
  out.rays = halves.size();
  out.max = halves.back();
  out.median = halves[halves.size() / 2];
  return out;
}

}  // namespace loom
