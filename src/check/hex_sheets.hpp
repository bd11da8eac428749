#pragma once
// The sheets of a hex mesh, found from its connectivity alone: the dual
// surfaces (Murdoch et al.'s spatial twist continuum). Each hex lies on three,
// one per direction; a sheet is a class of mesh edges under "parallel edges of
// one hex" (a hex's four edges of a direction cross the same sheet). Works on
// every hex whatever made it (woven, searched, from the database, filled), so
// it names the sheets of a whole closed mesh, not only of the weave's STC.
#include <array>
#include <cstdint>
#include <vector>

#include "src/mesh/hex_mesh.hpp"

namespace loom {

struct HexSheets {
  std::uint32_t count = 0;
  /// Per hex, the sheets its edges 0-1, 0-3 and 0-4 (VTK corners) cross.
  /// Sheets are numbered 0, 1, ... in order of first appearance (hex by hex,
  /// direction by direction), so the numbering is deterministic.
  std::vector<std::array<std::uint32_t, 3>> of_hex;
};

HexSheets hex_sheets(const HexMesh& mesh);

}  // namespace loom
