#pragma once
// A mesh as a file states it, before any check: points, and cells with their
// kind and where in the file they came from. Every reader produces one;
// to_quad_surface() and to_hex_mesh() apply the checks common to all formats, so
// every format rejects the same things with the same words.
#include <cstdint>
#include <string>
#include <vector>

#include "src/mesh/hex_mesh.hpp"
#include "src/mesh/quad_surface.hpp"

namespace loom {

enum class CellKind { vertex, line, triangle, quad, polygon, hexahedron, other_volume, unsupported };

/// Where a cell was found, for messages: "line 12", "cell 3", "element 17".
struct CellOrigin {
  const char* unit = "cell";
  std::int64_t number = 0;
};

struct RawCell {
  CellKind kind = CellKind::unsupported;
  std::vector<std::int64_t> nodes;  ///< 0-based, not yet range-checked
  CellOrigin origin;
  std::string type_name;  ///< e.g. "tetrahedron"; used in messages
};

struct RawMesh {
  std::vector<Vec3> points;
  std::vector<RawCell> cells;
  /// How the file numbers its nodes (OBJ and MSH from 1, the others from 0),
  /// so messages quote indices the way the file writes them.
  int node_numbering_base = 0;
};

/// Keeps the faces (vertices and line cells are ignored); rejects non-quad faces,
/// volume cells, out-of-range indices and non-finite coordinates.
QuadSurface to_quad_surface(RawMesh&& raw, const std::string& where);

/// Keeps the hexahedra (lower-dimensional cells are ignored); rejects other volume
/// cells, out-of-range indices and non-finite coordinates.
HexMesh to_hex_mesh(RawMesh&& raw, const std::string& where);

/// "line 12", "cell 3"...
std::string describe(const CellOrigin& origin);

}  // namespace loom
