#pragma once
// What the writers see: points and one block of same-shaped cells, with the
// per-format type codes. Writers print doubles with fmt's default "{}", the
// shortest text that reads back to the same double, so every write round-trips
// exactly and is deterministic.
#include <cstdint>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "src/mesh/hex_mesh.hpp"
#include "src/mesh/quad_surface.hpp"

namespace loom {

enum class CellShape { quad, hexahedron };

/// A value per cell, written where the format carries cell data (VTK
/// CELL_DATA, VTU CellData, MSH $ElementData, Exodus element variables).
/// Integer fields (codes such as `source`) are written as integers where the
/// format has them; their values must be whole numbers that fit in 32 bits.
struct CellField {
  enum class Kind { integer, real };
  std::string name;  ///< one word, at most 32 characters (Exodus's limit)
  std::vector<double> values;
  Kind kind = Kind::integer;
};

struct CellTable {
  const std::vector<Vec3>& points;
  CellShape shape;
  std::vector<std::uint32_t> connectivity;  ///< cell_count() * nodes_per_cell(), 0-based
  std::vector<CellField> fields;            ///< each with cell_count() values

  std::size_t nodes_per_cell() const { return shape == CellShape::quad ? 4 : 8; }
  std::size_t cell_count() const { return connectivity.size() / nodes_per_cell(); }
  int dimension() const { return shape == CellShape::quad ? 2 : 3; }
  int vtk_type() const { return shape == CellShape::quad ? 9 : 12; }  // VTK_QUAD, VTK_HEXAHEDRON
  int msh_type() const { return shape == CellShape::quad ? 3 : 5; }   // MSH 4-node quad, 8-node hex
};

/// Appends value `cell` of `field` to `out`: an integer field's as an integer,
/// a real field's in the shortest text that reads back to the same double.
void append_cell_value(fmt::memory_buffer& out, const CellField& field, std::size_t cell);

CellTable cell_table(const QuadSurface& surface);
CellTable cell_table(const HexMesh& mesh);

}  // namespace loom
