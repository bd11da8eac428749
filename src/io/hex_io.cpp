#include "src/io/hex_io.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

#include "src/io/formats.hpp"
#include "src/io/mesh_format.hpp"
#include "src/util/atomic_file.hpp"

namespace loom {

namespace {

// Fields come from Loom's own code, so a bad one is a programming error.
void check_field(const CellField& field, std::size_t hexes) {
  if (field.values.size() != hexes)
    throw std::invalid_argument("write_hex_mesh: field " + field.name + " does not have a value per hex");
  if (field.name.empty() || field.name.size() > 32)
    throw std::invalid_argument("write_hex_mesh: field name '" + field.name + "' is empty or over 32 characters");
  if (field.kind == CellField::Kind::integer)
    for (double v : field.values)
      if (!(v == std::trunc(v) && v >= std::numeric_limits<std::int32_t>::min() &&
            v <= std::numeric_limits<std::int32_t>::max()))
        throw std::invalid_argument("write_hex_mesh: integer field " + field.name + " has a value that is not a 32-bit integer");
}

}  // namespace

HexMesh read_hex_mesh(const std::filesystem::path& file) {
  return to_hex_mesh(read_raw_mesh(file, hex_format_of(file)), file.string());
}

void write_hex_mesh(const std::filesystem::path& file, const HexMesh& mesh, std::vector<CellField> fields) {
  for (const CellField& f : fields) check_field(f, mesh.hexes.size());
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
    case MeshFormat::exodus:  // binary, written by the Exodus library itself
      write_atomically(file, [&](const std::filesystem::path& tmp) { write_exodus(tmp, table, file.string()); });
      return;
    case MeshFormat::obj:
    case MeshFormat::off:
      break;
  }
  write_text_atomically(file, text);
}

}  // namespace loom
