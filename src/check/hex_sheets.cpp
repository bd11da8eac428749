#include "src/check/hex_sheets.hpp"

#include "src/check/disjoint_sets.hpp"
#include "src/check/hex_topology.hpp"

namespace loom {

namespace {

/// The local edges of each direction of a VTK hex, the first of each being
/// 0-1, 0-3 and 0-4.
constexpr std::array<std::array<int, 4>, 3> kParallelEdges{{{0, 2, 4, 6}, {3, 1, 7, 5}, {8, 9, 10, 11}}};

}  // namespace

HexSheets hex_sheets(const HexMesh& mesh) {
  const HexTopology topology = build_hex_topology(mesh);
  DisjointSets sets(topology.edge_count);
  for (std::size_t h = 0; h < mesh.hexes.size(); ++h)
    for (const auto& direction : kParallelEdges)
      for (int k = 1; k < 4; ++k)
        sets.unite(topology.hex_edges[12 * h + direction[0]], topology.hex_edges[12 * h + direction[k]]);
  HexSheets out;
  std::vector<std::uint32_t> number(topology.edge_count, UINT32_MAX);
  out.of_hex.resize(mesh.hexes.size());
  for (std::size_t h = 0; h < mesh.hexes.size(); ++h)
    for (int d = 0; d < 3; ++d) {
      std::uint32_t& n = number[sets.find(topology.hex_edges[12 * h + kParallelEdges[d][0]])];
      if (n == UINT32_MAX) n = out.count++;
      out.of_hex[h][d] = n;
    }
  return out;
}

}  // namespace loom
