#include "src/check/hex_boundary.hpp"

#include "src/check/hex_topology.hpp"

namespace loom {

QuadSurface hex_mesh_boundary(const HexMesh& mesh, std::vector<std::uint32_t>* mesh_node) {
  const HexTopology topo = build_hex_topology(mesh);
  QuadSurface surface;
  std::vector<std::uint32_t> renumbered(mesh.points.size(), kNoSide), original;
  for (std::uint32_t item = 0; item < topo.hex_faces.size(); ++item) {
    if (!topo.is_boundary_face(topo.hex_faces[item])) continue;
    Quad quad{};
    const auto nodes = face_nodes(mesh.hexes[item / 6], static_cast<int>(item % 6));
    for (int i = 0; i < 4; ++i) {
      std::uint32_t& mapped = renumbered[nodes[i]];
      if (mapped == kNoSide) {
        mapped = static_cast<std::uint32_t>(surface.points.size());
        surface.points.push_back(mesh.points[nodes[i]]);
        original.push_back(nodes[i]);
      }
      quad[i] = mapped;
    }
    surface.quads.push_back(quad);
  }
  if (mesh_node) *mesh_node = std::move(original);
  return surface;
}

}  // namespace loom
