#include "src/check/edge_valence.hpp"

#include "src/check/criteria.hpp"

namespace loom {

EdgeValences edge_valences(const HexMesh& mesh, const HexTopology& topo) {
  EdgeValences v;
  v.hexes_round.assign(topo.edge_count, 0);
  v.on_boundary.assign(topo.edge_count, false);
  v.node_on_boundary.assign(mesh.points.size(), false);
  for (std::size_t h = 0; h < mesh.hexes.size(); ++h) {
    for (int e = 0; e < 12; ++e) ++v.hexes_round[topo.hex_edges[12 * h + static_cast<std::size_t>(e)]];
    for (int f = 0; f < 6; ++f) {
      if (!topo.is_boundary_face(topo.hex_faces[6 * h + static_cast<std::size_t>(f)])) continue;
      for (std::uint32_t node : face_nodes(mesh.hexes[h], f)) v.node_on_boundary[node] = true;
      for (int e : kHexFaceEdges[static_cast<std::size_t>(f)])
        v.on_boundary[topo.hex_edges[12 * h + static_cast<std::size_t>(e)]] = true;
    }
  }
  return v;
}

std::map<std::uint32_t, std::size_t> interior_valence_histogram(const HexMesh& mesh) {
  std::map<std::uint32_t, std::size_t> histogram;
  if (!criteria::distinct_nodes(mesh).passed) return histogram;
  const HexTopology topo = build_hex_topology(mesh);
  const EdgeValences v = edge_valences(mesh, topo);
  for (std::uint32_t e = 0; e < topo.edge_count; ++e)
    if (!v.on_boundary[e]) ++histogram[v.hexes_round[e]];
  return histogram;
}

}  // namespace loom
