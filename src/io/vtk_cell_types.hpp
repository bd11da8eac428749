#pragma once
// VTK cell type codes (shared by legacy .vtk and XML .vtu) mapped to our kinds.
#include "src/io/raw_mesh.hpp"

namespace loom {

/// A RawCell for VTK cell type `vtk_type`. Types whose node order differs from
/// ours (VTK_PIXEL, VTK_VOXEL) are "unsupported" with a name saying so.
RawCell vtk_cell(int vtk_type, std::vector<std::int64_t> nodes, CellOrigin origin);

}  // namespace loom
