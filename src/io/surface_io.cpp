#include "src/io/surface_io.hpp"

#include "src/io/formats.hpp"
#include "src/io/mesh_format.hpp"
#include "src/util/atomic_file.hpp"

namespace loom {

QuadSurface read_surface(const std::filesystem::path& file) {
  return to_quad_surface(read_raw_mesh(file, surface_format_of(file)), file.string());
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
    case MeshFormat::exodus:  // surface_format_of refuses it
      break;
  }
  write_text_atomically(file, text);
}

}  // namespace loom
