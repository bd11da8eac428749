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

void append_cell_value(fmt::memory_buffer& out, const CellField& field, std::size_t cell) {
  const double value = field.values[cell];
  if (field.kind == CellField::Kind::integer)
    fmt::format_to(std::back_inserter(out), "{}", static_cast<std::int32_t>(value));
  else
    fmt::format_to(std::back_inserter(out), "{}", value);
}

CellTable cell_table(const QuadSurface& surface) { return {surface.points, CellShape::quad, flatten(surface.quads)}; }

CellTable cell_table(const HexMesh& mesh) { return {mesh.points, CellShape::hexahedron, flatten(mesh.hexes)}; }

}  // namespace loom
