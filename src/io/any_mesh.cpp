#include "src/io/any_mesh.hpp"

#include <algorithm>

#include "src/io/formats.hpp"
#include "src/io/mesh_format.hpp"

namespace loom {

std::variant<QuadSurface, HexMesh> read_surface_or_hex_mesh(const std::filesystem::path& file) {
  const std::string where = file.string();
  RawMesh raw = read_raw_mesh(file, surface_format_of(file));
  bool has_hex = std::any_of(raw.cells.begin(), raw.cells.end(),
                             [](const RawCell& c) { return c.kind == CellKind::hexahedron; });
  if (has_hex) return to_hex_mesh(std::move(raw), where);
  return to_quad_surface(std::move(raw), where);
}

}  // namespace loom
