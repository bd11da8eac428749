#include "src/io/mesh_format.hpp"

#include <algorithm>
#include <cctype>
#include <optional>
#include <string>

#include "src/util/error.hpp"

namespace loom {

namespace {

std::optional<MeshFormat> format_from_extension(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".obj") return MeshFormat::obj;
  if (ext == ".off") return MeshFormat::off;
  if (ext == ".vtk") return MeshFormat::vtk;
  if (ext == ".vtu") return MeshFormat::vtu;
  if (ext == ".msh") return MeshFormat::msh;
  if (ext == ".exo" || ext == ".e") return MeshFormat::exodus;
  return std::nullopt;
}

std::string shown_extension(const std::filesystem::path& file) {
  auto ext = file.extension().string();
  return ext.empty() ? std::string("no extension") : fmt::format("extension '{}'", ext);
}

}  // namespace

MeshFormat surface_format_of(const std::filesystem::path& file) {
  auto format = format_from_extension(file);
  if (!format || *format == MeshFormat::exodus)
    fail_input(file.string(), fmt::format("unknown surface file format ({})", shown_extension(file)),
               "use .obj, .off, .vtk, .vtu or .msh");
  return *format;
}

MeshFormat hex_format_of(const std::filesystem::path& file) {
  auto format = format_from_extension(file);
  if (!format || *format == MeshFormat::obj || *format == MeshFormat::off)
    fail_input(file.string(), fmt::format("unknown hex mesh file format ({})", shown_extension(file)),
               "use .vtk, .vtu, .msh, or .exo or .e (Exodus II)");
  return *format;
}

std::string_view format_name(MeshFormat format) {
  switch (format) {
    case MeshFormat::obj:
      return "OBJ";
    case MeshFormat::off:
      return "OFF";
    case MeshFormat::vtk:
      return "legacy VTK";
    case MeshFormat::vtu:
      return "VTU";
    case MeshFormat::msh:
      return "MSH";
    case MeshFormat::exodus:
      return "Exodus II";
  }
  return "?";
}

}  // namespace loom
