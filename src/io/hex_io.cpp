#include "src/io/hex_io.hpp"

#include "src/io/formats.hpp"
#include "src/io/mesh_format.hpp"
#include "src/util/atomic_file.hpp"

namespace loom {

HexMesh read_hex_mesh(const std::filesystem::path& file) {
  return to_hex_mesh(read_raw_mesh(file, hex_format_of(file)), file.string());
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
