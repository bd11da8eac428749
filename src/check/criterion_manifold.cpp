// Criterion 4: the complex is a 3-manifold with boundary.
//
// Edge test: around an edge, the hexes holding it are joined through the faces
// holding it (each face in two hexes joins them). One piece with no boundary
// face is a cycle; one piece with two boundary faces is a fan.
//
// Node test: the link of node v is the 2-complex with a vertex per edge at v, a
// side per face at v and a triangle per hex at v. Its pieces are the hexes at
// v joined through shared faces at v; its Euler characteristic is
// edges(v) - faces(v) + hexes(v). When the edge test holds at v's edges the
// link is a surface, and a connected surface with chi = 2 and no boundary is a
// sphere, while one with chi = 1 and a boundary is a disk (chi = 2 - 2g - b for
// orientable, 2 - k - b otherwise, b >= 1, forces g = k = 0 and b = 1). The link
// has a boundary exactly when v lies on a boundary face.
#include "src/check/criteria.hpp"
#include "src/check/disjoint_sets.hpp"

namespace loom::criteria {

namespace {

/// Calls join(local_a, local_b) for each pair of matching corners (or edges)
/// of the two sides of every face held by exactly two hexes.
template <class Join>
void for_each_interior_face(const HexTopology& topo, Join join) {
  for (std::uint32_t f = 0; f < topo.face_count; ++f) {
    if (topo.face_hex_count[f] != 2) continue;
    const auto [a, b] = topo.face_sides[f];
    join(a / 6, static_cast<int>(a % 6), b / 6, static_cast<int>(b % 6));
  }
}

std::string check_edges(const HexMesh& mesh, const HexTopology& topo, std::size_t& bad) {
  const std::size_t hexes = mesh.hexes.size();
  DisjointSets pieces(12 * hexes);
  for_each_interior_face(topo, [&](std::uint32_t ha, int fa, std::uint32_t hb, int fb) {
    for (int le_a : kHexFaceEdges[fa])
      for (int le_b : kHexFaceEdges[fb])
        if (topo.hex_edges[12 * ha + le_a] == topo.hex_edges[12 * hb + le_b])
          pieces.unite(12 * ha + le_a, 12 * hb + le_b);
  });
  std::vector<std::uint32_t> piece_count(topo.edge_count, 0), boundary_faces(topo.edge_count, 0);
  for (std::uint32_t item = 0; item < 12 * hexes; ++item)
    if (pieces.is_root(item)) ++piece_count[topo.hex_edges[item]];
  for (std::uint32_t f = 0; f < topo.face_count; ++f) {
    if (!topo.is_boundary_face(f)) continue;
    const std::uint32_t side = topo.face_sides[f][0];
    for (int le : kHexFaceEdges[side % 6]) ++boundary_faces[topo.hex_edges[12 * (side / 6) + le]];
  }
  std::string first;
  for (std::uint32_t e = 0; e < topo.edge_count; ++e) {
    if (piece_count[e] == 1 && (boundary_faces[e] == 0 || boundary_faces[e] == 2)) continue;
    if (bad++ > 0) continue;
    const std::uint32_t item = topo.edge_first[e];
    const Hex& hex = mesh.hexes[item / 12];
    const auto& c = kHexEdgeCorners[item % 12];
    first = fmt::format("around edge {}-{} the hexes form {} piece{} with {} boundary face{}, not one cycle or one fan",
                        std::min(hex[c[0]], hex[c[1]]), std::max(hex[c[0]], hex[c[1]]), piece_count[e],
                        piece_count[e] == 1 ? "" : "s", boundary_faces[e], boundary_faces[e] == 1 ? "" : "s");
  }
  return first;
}

std::string check_nodes(const HexMesh& mesh, const HexTopology& topo, std::size_t& bad) {
  const std::size_t hexes = mesh.hexes.size(), nodes = mesh.points.size();
  DisjointSets pieces(8 * hexes);
  for_each_interior_face(topo, [&](std::uint32_t ha, int fa, std::uint32_t hb, int fb) {
    for (int ca : kHexFaceCorners[fa])
      for (int cb : kHexFaceCorners[fb])
        if (mesh.hexes[ha][ca] == mesh.hexes[hb][cb]) pieces.unite(8 * ha + ca, 8 * hb + cb);
  });
  std::vector<std::uint32_t> piece_count(nodes, 0);
  std::vector<std::int64_t> link_euler(nodes, 0);
  std::vector<char> used(nodes, 0), on_boundary(nodes, 0);
  for (std::uint32_t item = 0; item < 8 * hexes; ++item) {
    const std::uint32_t v = mesh.hexes[item / 8][item % 8];
    used[v] = 1;
    ++link_euler[v];  // a triangle of v's link
    if (pieces.is_root(item)) ++piece_count[v];
  }
  for (std::uint32_t f = 0; f < topo.face_count; ++f) {
    const std::uint32_t side = topo.face_sides[f][0];
    for (std::uint32_t v : face_nodes(mesh.hexes[side / 6], static_cast<int>(side % 6))) {
      --link_euler[v];  // a side of v's link
      if (topo.is_boundary_face(f)) on_boundary[v] = 1;
    }
  }
  for (std::uint32_t e = 0; e < topo.edge_count; ++e) {
    const std::uint32_t item = topo.edge_first[e];
    for (int c : kHexEdgeCorners[item % 12]) ++link_euler[mesh.hexes[item / 12][c]];  // a vertex of v's link
  }
  std::string first;
  for (std::uint32_t v = 0; v < nodes; ++v) {
    if (!used[v]) continue;
    const std::int64_t wanted = on_boundary[v] ? 1 : 2;
    if (piece_count[v] == 1 && link_euler[v] == wanted) continue;
    if (bad++ > 0) continue;
    const char* kind = on_boundary[v] ? "boundary" : "interior";
    if (piece_count[v] != 1)
      first = fmt::format("the link of {} node {} has {} pieces, not one {}", kind, v, piece_count[v],
                          on_boundary[v] ? "disk" : "sphere");
    else
      first = fmt::format("the link of {} node {} has Euler characteristic {}, but a {} has {}", kind, v, link_euler[v],
                          on_boundary[v] ? "disk" : "sphere", wanted);
  }
  return first;
}

}  // namespace

CriterionResult manifold(const HexMesh& mesh, const HexTopology& topo) {
  std::size_t bad_edges = 0, bad_nodes = 0;
  const std::string edge_problem = check_edges(mesh, topo, bad_edges);
  const std::string node_problem = check_nodes(mesh, topo, bad_nodes);
  if (bad_edges == 0 && bad_nodes == 0) return passed(4);
  const std::string counts = fmt::format("{} bad edge{}, {} bad node{}", bad_edges, bad_edges == 1 ? "" : "s",
                                         bad_nodes, bad_nodes == 1 ? "" : "s");
  return failed(4, fmt::format("{} ({})", bad_edges > 0 ? edge_problem : node_problem, counts));
}

}  // namespace loom::criteria
