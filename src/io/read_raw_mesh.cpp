#include "src/io/formats.hpp"
#include "src/io/text_scanner.hpp"
#include "src/util/error.hpp"

namespace loom {

RawMesh read_raw_mesh(const std::filesystem::path& file, MeshFormat format) {
  const std::string where = file.string();
  switch (format) {
    case MeshFormat::obj: return parse_obj(read_input_file(file), where);
    case MeshFormat::off: return parse_off(read_input_file(file), where);
    case MeshFormat::vtk: return parse_legacy_vtk(read_input_file(file), where);
    case MeshFormat::vtu: return parse_vtu(read_input_file(file), where);
    case MeshFormat::msh: return read_msh(file);
    case MeshFormat::exodus:
      fail_input(where, "Loom writes Exodus II files but does not read them",
                 "give the mesh as .vtk, .vtu or .msh (e.g. convert it with ParaView or Gmsh)");
  }
  return {};
}

}  // namespace loom
