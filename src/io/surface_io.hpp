#pragma once
// Reading and writing quad surface meshes. The format is chosen by extension:
// .obj .off .vtk (legacy) .vtu .msh (2.2 and 4.1). Reading only parses; whether
// the surface can bound a hex mesh is decided by validate_surface().
#include <filesystem>

#include "src/mesh/quad_surface.hpp"

namespace loom {

/// Reads a surface mesh. Throws InputError (one line: file, what, what to do) for
/// a missing, unreadable, truncated or malformed file, an unknown extension,
/// NaN/inf coordinates, out-of-range indices, and any face that is not a quad.
QuadSurface read_surface(const std::filesystem::path& file);

/// Writes a surface mesh atomically; the format follows the extension.
void write_surface(const std::filesystem::path& file, const QuadSurface& surface);

}  // namespace loom
