#pragma once
// Which file format a path names, decided by its extension (case-insensitive).
#include <filesystem>
#include <string_view>

namespace loom {

enum class MeshFormat { obj, off, vtk, vtu, msh, exodus };

/// The format of a surface file (.obj .off .vtk .vtu .msh); InputError otherwise.
MeshFormat surface_format_of(const std::filesystem::path& file);

/// The format of a hex mesh file (.vtk .vtu .msh, and .exo .e for Exodus II,
/// which Loom writes but does not read); InputError otherwise.
MeshFormat hex_format_of(const std::filesystem::path& file);

std::string_view format_name(MeshFormat format);

}  // namespace loom
