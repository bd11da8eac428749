#include "src/io/hex_io.hpp"

#include <stdexcept>

#include "src/io/formats.hpp"
#include "src/io/mesh_format.hpp"
#include "src/util/atomic_file.hpp"

namespace loom {

HexMesh read_hex_mesh(const std::filesystem::path& file) {
  return to_hex_mesh(read_raw_mesh(file, hex_format_of(file)), file.string());
}

void write_hex_mesh(const std::filesystem::path& file, const HexMesh& mesh, std::vector<CellField> fields) {
  for (const CellField& f : fields)
    if (f.values.size() != mesh.hexes.size())
      throw std::invalid_argument("write_hex_mesh: field " + f.name + " does not have a value per hex");
  CellTable table = cell_table(mesh);
  table.fields = std::move(fields);
  std::string text;
  switch (hex_format_of(file)) {
    case MeshFormat::vtk:
      text = legacy_vtk_text(table);
      break;
    case MeshFormat::vtu:
      text = vtu_text(table);
      break;
    case MeshFormat::msh:
      text = msh_text(table);
      break;
    case MeshFormat::obj:
    case MeshFormat::off:
      break;
  }
  write_text_atomically(file, text);
}

}  // namespace loom
