#include "src/check/hex_topology.hpp"

#include <algorithm>
#include <bit>

#include "src/check/key_numbering.hpp"

namespace loom {

std::array<std::uint32_t, 4> face_nodes(const Hex& hex, int local_face) {
  const auto& c = kHexFaceCorners[local_face];
  return {hex[c[0]], hex[c[1]], hex[c[2]], hex[c[3]]};
}

HexTopology build_hex_topology(const HexMesh& mesh) {
  const std::size_t hexes = mesh.hexes.size(), nodes = mesh.points.size();
  HexTopology topo;

  auto face_key = [&](std::size_t item) {
    auto key = face_nodes(mesh.hexes[item / 6], static_cast<int>(item % 6));
    std::sort(key.begin(), key.end());
    return key;
  };
  KeyNumbering faces = number_by_key<4>(6 * hexes, nodes, face_key);
  topo.face_count = faces.distinct;
  topo.hex_faces = std::move(faces.number);
  topo.face_hex_count.assign(topo.face_count, 0);
  topo.face_sides.assign(topo.face_count, {kNoSide, kNoSide});
  for (std::uint32_t item = 0; item < topo.hex_faces.size(); ++item) {
    const std::uint32_t f = topo.hex_faces[item];
    const std::uint32_t held = topo.face_hex_count[f]++;
    if (held < 2) topo.face_sides[f][held] = item;
  }

  auto edge_key = [&](std::size_t item) {
    const Hex& hex = mesh.hexes[item / 12];
    const auto& c = kHexEdgeCorners[item % 12];
    return std::array<std::uint32_t, 2>{std::min(hex[c[0]], hex[c[1]]), std::max(hex[c[0]], hex[c[1]])};
  };
  KeyNumbering edges = number_by_key<2>(12 * hexes, nodes, edge_key);
  topo.edge_count = edges.distinct;
  topo.hex_edges = std::move(edges.number);
  topo.edge_first.assign(topo.edge_count, kNoSide);
  for (std::uint32_t item = 0; item < topo.hex_edges.size(); ++item)
    if (topo.edge_first[topo.hex_edges[item]] == kNoSide) topo.edge_first[topo.hex_edges[item]] = item;
  return topo;
}

bool is_hex_edge_or_face(unsigned mask) {
  if (std::popcount(mask) == 2) {
    for (auto [a, b] : kHexEdgeCorners)
      if (mask == ((1u << a) | (1u << b))) return true;
    return false;
  }
  if (std::popcount(mask) != 4) return false;
  for (const auto& corners : kHexFaceCorners) {
    unsigned face = 0;
    for (int k : corners) face |= 1u << k;
    if (mask == face) return true;
  }
  return false;
}

bool hexes_meet_properly(const Hex& a, const Hex& b) {
  unsigned in_a = 0, in_b = 0;
  for (int j = 0; j < 8; ++j)
    for (int k = 0; k < 8; ++k)
      if (a[j] == b[k]) in_a |= 1u << j, in_b |= 1u << k;
  if (std::popcount(in_a) <= 1) return true;
  return is_hex_edge_or_face(in_a) && is_hex_edge_or_face(in_b);
}

}  // namespace loom
