#pragma once
// The faces and edges of a hex mesh, numbered once, with which hexes hold them.
// Faces are identified by their node set, edges by their two nodes; both are
// numbered in lexicographic order of their sorted nodes, so numbering is
// deterministic. Building is linear in the number of hexes (bucketed by the
// smallest node, small sorts inside each bucket).
#include <array>
#include <cstdint>
#include <vector>

#include "src/mesh/hex_mesh.hpp"

namespace loom {

/// Local corners of each face of a VTK hex, counter-clockwise seen from outside
/// a positively oriented hex.
inline constexpr std::array<std::array<int, 4>, 6> kHexFaceCorners{
    {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}};
/// Local corners of each edge of a VTK hex.
inline constexpr std::array<std::array<int, 2>, 12> kHexEdgeCorners{
    {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}}};
/// Local edges of each face: side i joins face corners i and i+1.
inline constexpr std::array<std::array<int, 4>, 6> kHexFaceEdges{
    {{3, 2, 1, 0}, {4, 5, 6, 7}, {0, 9, 4, 8}, {1, 10, 5, 9}, {2, 11, 6, 10}, {3, 8, 7, 11}}};

inline constexpr std::uint32_t kNoSide = 0xffffffffu;

struct HexTopology {
  std::uint32_t face_count = 0, edge_count = 0;
  std::vector<std::uint32_t> hex_faces;       ///< [6*hex + local face] -> face
  std::vector<std::uint32_t> hex_edges;       ///< [12*hex + local edge] -> edge
  std::vector<std::uint32_t> face_hex_count;  ///< hexes holding each face (a duplicated hex counts twice)
  /// The first two holders of each face as 6*hex + local face, in hex order;
  /// kNoSide when the face has fewer.
  std::vector<std::array<std::uint32_t, 2>> face_sides;
  std::vector<std::uint32_t> edge_first;  ///< a holder of each edge, 12*hex + local edge

  bool is_boundary_face(std::uint32_t face) const { return face_hex_count[face] == 1; }
};

/// Whether corners `mask` of a hex (bit k: VTK corner k) are one of its
/// edges (2 corners) or one of its faces (4 corners).
bool is_hex_edge_or_face(unsigned corner_mask);

/// Whether two hexes meet properly by their nodes: in nothing, one node, or
/// one edge or one face of both (criterion 3 for one pair).
bool hexes_meet_properly(const Hex& a, const Hex& b);

/// Precondition: every hex has 8 distinct nodes, all < mesh.points.size()
/// (criterion 1), and 12 * hexes fits in 32 bits.
HexTopology build_hex_topology(const HexMesh& mesh);

/// The nodes of local face `local_face` of `hex`, in kHexFaceCorners order.
std::array<std::uint32_t, 4> face_nodes(const Hex& hex, int local_face);

}  // namespace loom
