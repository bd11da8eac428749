// Criterion 5: the complex is one solid whose Euler characteristic fits its
// boundary. For a compact 3-manifold chi(M) = chi(boundary) / 2, and a
// boundary component of genus g has chi = 2 - 2g: a ball gives 1, a solid
// torus 0. The hexes must also form one piece (joined through faces).
#include <map>

#include "src/check/criteria.hpp"
#include "src/check/disjoint_sets.hpp"

namespace loom::criteria {

namespace {

struct SurfaceCounts {
  std::int64_t nodes = 0, edges = 0, faces = 0;
  std::int64_t euler() const { return nodes - edges + faces; }
};

std::size_t hex_pieces(const HexMesh& mesh, const HexTopology& topo) {
  DisjointSets pieces(mesh.hexes.size());
  for (std::uint32_t f = 0; f < topo.face_count; ++f)
    if (topo.face_hex_count[f] >= 2) pieces.unite(topo.face_sides[f][0] / 6, topo.face_sides[f][1] / 6);
  std::size_t count = 0;
  for (std::uint32_t h = 0; h < mesh.hexes.size(); ++h) count += pieces.is_root(h);
  return count;
}

/// Counts of each boundary component, keyed by its smallest node.
std::map<std::uint32_t, SurfaceCounts> boundary_components(const HexMesh& mesh, const HexTopology& topo) {
  DisjointSets joined(mesh.points.size());
  std::vector<char> on_boundary(mesh.points.size(), 0), edge_on_boundary(topo.edge_count, 0);
  for (std::uint32_t f = 0; f < topo.face_count; ++f) {
    if (!topo.is_boundary_face(f)) continue;
    const std::uint32_t side = topo.face_sides[f][0];
    const auto nodes = face_nodes(mesh.hexes[side / 6], static_cast<int>(side % 6));
    for (std::uint32_t v : nodes) {
      on_boundary[v] = 1;
      joined.unite(nodes[0], v);
    }
    for (int le : kHexFaceEdges[side % 6]) edge_on_boundary[topo.hex_edges[12 * (side / 6) + le]] = 1;
  }
  std::map<std::uint32_t, SurfaceCounts> components;
  for (std::uint32_t v = 0; v < mesh.points.size(); ++v)
    if (on_boundary[v]) ++components[joined.find(v)].nodes;
  for (std::uint32_t e = 0; e < topo.edge_count; ++e) {
    if (!edge_on_boundary[e]) continue;
    const std::uint32_t item = topo.edge_first[e];
    ++components[joined.find(mesh.hexes[item / 12][kHexEdgeCorners[item % 12][0]])].edges;
  }
  for (std::uint32_t f = 0; f < topo.face_count; ++f) {
    if (!topo.is_boundary_face(f)) continue;
    const std::uint32_t side = topo.face_sides[f][0];
    ++components[joined.find(face_nodes(mesh.hexes[side / 6], static_cast<int>(side % 6))[0])].faces;
  }
  return components;
}

}  // namespace

CriterionResult euler_characteristic(const HexMesh& mesh, const HexTopology& topo, BoundaryShape& shape) {
  const std::size_t pieces = hex_pieces(mesh, topo);
  const auto components = boundary_components(mesh, topo);
  shape.components = components.size();
  shape.genus = 0;

  std::vector<char> used(mesh.points.size(), 0);
  for (const Hex& hex : mesh.hexes)
    for (std::uint32_t v : hex) used[v] = 1;
  std::int64_t nodes = 0;
  for (char u : used) nodes += u;
  const std::int64_t euler =
      nodes - std::int64_t(topo.edge_count) + std::int64_t(topo.face_count) - std::int64_t(mesh.hexes.size());
  const std::string counts = fmt::format("V - E + F - C = {} - {} + {} - {} = {}", nodes, topo.edge_count,
                                         topo.face_count, mesh.hexes.size(), euler);

  if (pieces != 1) return failed(5, fmt::format("the hexes form {} separate pieces, not one solid", pieces));
  if (components.empty()) return failed(5, "the mesh has no boundary faces, so it bounds no solid");
  std::int64_t boundary_euler = 0;
  for (const auto& [root, c] : components) {
    if (c.euler() > 2 || c.euler() % 2 != 0)
      return failed(5, fmt::format("the boundary piece through node {} has Euler characteristic {}, "
                                   "which no closed orientable surface has",
                                   root, c.euler()));
    shape.genus += static_cast<int>((2 - c.euler()) / 2);
    boundary_euler += c.euler();
  }
  const std::int64_t expected = boundary_euler / 2;
  if (euler == expected) return passed(5);
  const std::string bounded_by = components.size() == 1
                                     ? fmt::format("one surface of genus {}", shape.genus)
                                     : fmt::format("{} surfaces of total genus {}", components.size(), shape.genus);
  return failed(5, fmt::format("{}, but a solid bounded by {} has {}", counts, bounded_by, expected));
}

}  // namespace loom::criteria
