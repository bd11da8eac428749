#pragma once
// Reading and writing hexahedral meshes: .vtk (legacy), .vtu, .msh (MSH 4.1),
// and writing (only) Exodus II, .exo or .e; the format is chosen by extension,
// nodes are in VTK order in memory. Writes are atomic.
#include <filesystem>

#include "src/io/cell_table.hpp"
#include "src/mesh/hex_mesh.hpp"

namespace loom {

/// Reads a hex mesh. Throws InputError for unreadable or malformed files and for
/// any volume cell that is not a hexahedron, and for Exodus files. Boundary
/// quads stored in the file are ignored.
HexMesh read_hex_mesh(const std::filesystem::path& file);

/// Writes a hex mesh atomically; the format follows the extension. `fields`
/// (a value per hex each) go into the file as cell data. Throws
/// std::invalid_argument for a malformed field (wrong count, name not 1-32
/// characters, an integer field's value not a 32-bit integer).
void write_hex_mesh(const std::filesystem::path& file, const HexMesh& mesh, std::vector<CellField> fields = {});

}  // namespace loom
