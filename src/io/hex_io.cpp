#include "src/io/hex_io.hpp"

#include "src/io/formats.hpp"
#include "src/io/mesh_format.hpp"
#include "src/io/text_scanner.hpp"
#include "src/util/atomic_file.hpp"

namespace loom {

HexMesh read_hex_mesh(const std::filesystem::path& file) {
  const std::string where = file.string();
  switch (hex_format_of(file)) {
    case MeshFormat::vtk:
      return to_hex_mesh(parse_legacy_vtk(read_input_file(file), where), where);
    case MeshFormat::vtu:
      return to_hex_mesh(parse_vtu(read_input_file(file), where), where);
    case MeshFormat::msh:
      return to_hex_mesh(read_msh(file), where);
    case MeshFormat::obj:
    case MeshFormat::off:
      break;  // refused by hex_format_of
  }
  return {};
}

void write_hex_mesh(const std::filesystem::path& file, const HexMesh& mesh) {
  std::string text;
  switch (hex_format_of(file)) {
    case MeshFormat::vtk:
      text = legacy_vtk_text(cell_table(mesh));
      break;
    case MeshFormat::vtu:
      text = vtu_text(cell_table(mesh));
      break;
    case MeshFormat::msh:
      text = msh_text(cell_table(mesh));
      break;
    case MeshFormat::obj:
    case MeshFormat::off:
      break;
  }
  write_text_atomically(file, text);
}

}  // namespace loom
