#include "src/geometry/boundary_layer.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <span>
#include <stdexcept>

#include "src/check/hex_topology.hpp"

namespace loom::geometry {

namespace {

using Quad = std::array<std::uint32_t, 4>;

Quad sorted(Quad q) {
  std::sort(q.begin(), q.end());
  return q;
}

}  // namespace

BoundaryLayerReport pillow_boundary_layer(HexMesh& mesh, std::vector<bool>& fixed) {
  return pillow_region(mesh, 0, mesh.hexes.size(), fixed);
}

BoundaryLayerReport pillow_region(HexMesh& mesh, std::size_t first, std::size_t last, std::vector<bool>& fixed) {
  if (fixed.size() != mesh.points.size())
    throw std::invalid_argument("pillow_region: fixed flags and nodes differ in number");
  if (first > last || last > mesh.hexes.size()) throw std::invalid_argument("pillow_region: hexes out of range");
  const auto region = std::span(mesh.hexes).subspan(first, last - first);
  std::map<Quad, int> uses;
  for (const Hex& h : region)
    for (const auto& f : kHexFaceCorners) ++uses[sorted({h[f[0]], h[f[1]], h[f[2]], h[f[3]]})];

  std::vector<Quad> boundary;
  // Each boundary quad turned to face into its hex: the new hex's bottom,
  // with its top (the copies) on that side.
  for (const Hex& h : region)
    for (const auto& f : kHexFaceCorners) {
      const Quad q{h[f[3]], h[f[2]], h[f[1]], h[f[0]]};
      if (uses[sorted(q)] == 1) boundary.push_back(q);
    }

  constexpr std::uint32_t kNone = ~0u;
  std::vector<std::uint32_t> copy(mesh.points.size(), kNone);
  BoundaryLayerReport report;
  for (const Quad& q : boundary)
    for (std::uint32_t v : q)
      if (copy[v] == kNone) {
        copy[v] = static_cast<std::uint32_t>(mesh.points.size());
        mesh.points.push_back(mesh.points[v]);
        fixed.push_back(false);
        ++report.nodes_added;
      }
  for (Hex& h : std::span(mesh.hexes).subspan(first, last - first))
    for (std::uint32_t& v : h)
      if (copy[v] != kNone) v = copy[v];
  for (const Quad& q : boundary)
    mesh.hexes.push_back({q[0], q[1], q[2], q[3], copy[q[0]], copy[q[1]], copy[q[2]], copy[q[3]]});
  report.hexes_added = boundary.size();
  return report;
}

bool remove_boundary_layer(HexMesh& mesh, std::size_t hexes) {
  if (hexes > mesh.hexes.size()) return false;
  const std::size_t first = mesh.hexes.size() - hexes;
  std::map<std::uint32_t, std::uint32_t> original_of;  // copy -> the boundary node it copies
  std::set<std::uint32_t> boundary;
  for (std::size_t h = first; h < mesh.hexes.size(); ++h)
    for (int k = 0; k < 4; ++k) {
      const std::uint32_t a = mesh.hexes[h][k], copy = mesh.hexes[h][k + 4];
      if (original_of.emplace(copy, a).first->second != a) return false;
      boundary.insert(a);
    }
  std::vector<Hex> kept(mesh.hexes.begin(), mesh.hexes.begin() + static_cast<std::ptrdiff_t>(first));
  for (Hex& h : kept)
    for (std::uint32_t& v : h) {
      if (boundary.contains(v)) return false;  // a layer's boundary node in a hex of the rest
      if (auto it = original_of.find(v); it != original_of.end()) v = it->second;
    }
  mesh.hexes = std::move(kept);
  return true;
}

}  // namespace loom::geometry
