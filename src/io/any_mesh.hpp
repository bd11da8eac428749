#pragma once
// For commands that take "a hex mesh, or a surface" (`loom stc`).
#include <filesystem>
#include <variant>

#include "src/mesh/hex_mesh.hpp"
#include "src/mesh/quad_surface.hpp"

namespace loom {

/// Reads `file` as a hex mesh if it holds any hexahedron, else as a quad
/// surface; throws InputError as read_surface / read_hex_mesh do.
std::variant<QuadSurface, HexMesh> read_surface_or_hex_mesh(const std::filesystem::path& file);

}  // namespace loom
