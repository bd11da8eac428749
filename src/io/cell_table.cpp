#include "src/io/cell_table.hpp"

namespace loom {

namespace {
template <std::size_t N>
std::vector<std::uint32_t> flatten(const std::vector<std::array<std::uint32_t, N>>& cells) {
  std::vector<std::uint32_t> flat;
  flat.reserve(cells.size() * N);
  for (const auto& cell : cells) flat.insert(flat.end(), cell.begin(), cell.end());
  return flat;
}
}  // namespace

CellTable cell_table(const QuadSurface& surface) { return {surface.points, CellShape::quad, flatten(surface.quads)}; }

CellTable cell_table(const HexMesh& mesh) { return {mesh.points, CellShape::hexahedron, flatten(mesh.hexes)}; }

}  // namespace loom
