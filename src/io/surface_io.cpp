#include "src/io/surface_io.hpp"

#include "src/io/formats.hpp"
#include "src/io/mesh_format.hpp"
#include "src/io/text_scanner.hpp"
#include "src/util/atomic_file.hpp"

namespace loom {

QuadSurface read_surface(const std::filesystem::path& file) {
  const std::string where = file.string();
  switch (surface_format_of(file)) {
    case MeshFormat::obj:
      return to_quad_surface(parse_obj(read_input_file(file), where), where);
    case MeshFormat::off:
      return to_quad_surface(parse_off(read_input_file(file), where), where);
    case MeshFormat::vtk:
      return to_quad_surface(parse_legacy_vtk(read_input_file(file), where), where);
    case MeshFormat::vtu:
      return to_quad_surface(parse_vtu(read_input_file(file), where), where);
    case MeshFormat::msh:
      return to_quad_surface(read_msh(file), where);
  }
  return {};
}

void write_surface(const std::filesystem::path& file, const QuadSurface& surface) {
  std::string text;
  switch (surface_format_of(file)) {
    case MeshFormat::obj:
      text = obj_text(surface);
      break;
    case MeshFormat::off:
      text = off_text(surface);
      break;
    case MeshFormat::vtk:
      text = legacy_vtk_text(cell_table(surface));
      break;
    case MeshFormat::vtu:
      text = vtu_text(cell_table(surface));
      break;
    case MeshFormat::msh:
      text = msh_text(cell_table(surface));
      break;
  }
  write_text_atomically(file, text);
}

}  // namespace loom
