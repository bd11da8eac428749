#pragma once
// The per-format readers and writers behind surface_io and hex_io. Parsers turn
// a file's text into a RawMesh (checked later, the same way for every format);
// writers turn a mesh into the file's full text. See docs/formats.md.
#include <filesystem>
#include <string>
#include <string_view>

#include "src/io/cell_table.hpp"
#include "src/io/mesh_format.hpp"
#include "src/io/raw_mesh.hpp"

namespace loom {

/// Reads `file` in `format` into a RawMesh (the one place formats are dispatched).
RawMesh read_raw_mesh(const std::filesystem::path& file, MeshFormat format);

RawMesh parse_obj(std::string_view text, const std::string& where);
std::string obj_text(const QuadSurface& surface);

RawMesh parse_off(std::string_view text, const std::string& where);
std::string off_text(const QuadSurface& surface);

/// Legacy VTK: UNSTRUCTURED_GRID or POLYDATA, ASCII or BINARY.
RawMesh parse_legacy_vtk(std::string_view text, const std::string& where);
std::string legacy_vtk_text(const CellTable& table);

/// VTK XML UnstructuredGrid with ASCII data arrays.
RawMesh parse_vtu(std::string_view text, const std::string& where);
std::string vtu_text(const CellTable& table);

/// Gmsh MSH 2.2 or 4.1: ASCII by our parser, binary through Gmsh.
RawMesh read_msh(const std::filesystem::path& file);
RawMesh parse_msh_ascii(std::string_view text, const std::string& where);
/// Any MSH file Gmsh reads, through the Gmsh API in a child process.
RawMesh read_msh_with_gmsh(const std::filesystem::path& file);
/// MSH 4.1 ASCII.
std::string msh_text(const CellTable& table);

/// Exodus II through the SEACAS Exodus library (binary netCDF): writes the hex
/// table to `file` itself, naming `shown_file` in errors (InputError, one line).
/// See exodus_format.cpp for what the file holds.
void write_exodus(const std::filesystem::path& file, const CellTable& table, const std::string& shown_file);

}  // namespace loom
