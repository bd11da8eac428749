#include "src/io/any_mesh.hpp"

#include <algorithm>

#include "src/io/formats.hpp"
#include "src/io/mesh_format.hpp"
#include "src/io/text_scanner.hpp"

namespace loom {

std::variant<QuadSurface, HexMesh> read_surface_or_hex_mesh(const std::filesystem::path& file) {
  const std::string where = file.string();
  RawMesh raw;
  switch (surface_format_of(file)) {
    case MeshFormat::obj: raw = parse_obj(read_input_file(file), where); break;
    case MeshFormat::off: raw = parse_off(read_input_file(file), where); break;
    case MeshFormat::vtk: raw = parse_legacy_vtk(read_input_file(file), where); break;
    case MeshFormat::vtu: raw = parse_vtu(read_input_file(file), where); break;
    case MeshFormat::msh: raw = read_msh(file); break;
  }
  bool has_hex = std::any_of(raw.cells.begin(), raw.cells.end(),
                             [](const RawCell& c) { return c.kind == CellKind::hexahedron; });
  if (has_hex) return to_hex_mesh(std::move(raw), where);
  return to_quad_surface(std::move(raw), where);
}

}  // namespace loom
