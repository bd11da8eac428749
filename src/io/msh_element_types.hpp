#pragma once
// Gmsh MSH element type codes: their dimension, node count and name.
#include <optional>

#include "src/io/raw_mesh.hpp"

namespace loom {

struct MshElementType {
  int dimension;
  int node_count;
  const char* name;
};

/// The element type with code `type`, if Loom knows it (first and second order
/// points, lines, triangles, quads, tetrahedra, hexahedra, prisms, pyramids).
std::optional<MshElementType> msh_element_type(int type);

/// Our kind for an MSH element: 4-node quads and 8-node hexahedra are the ones
/// Loom uses; others are named so the checks can reject them clearly.
CellKind msh_cell_kind(int type, int dimension);

}  // namespace loom
